"""ctest python_pip_install_venv: `pip install .` into a fresh virtual environment, then the
module's tests run with the installed package (not the build tree).

The venv sees Debian's numpy and pytest (--system-site-packages); nothing comes from the Python
package index (pip --no-index). The module is built against the singlestrip installed in
--prefix (the package_install fixture), so only the bindings compile: `pip install .` without -C
builds the library too (README, "Python").
"""
import argparse
import os
import shutil
import subprocess
import sys
import time


def run(cmd, **kw):
    print("+", " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, **kw)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--source", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--prefix", required=True)
    a = ap.parse_args()
    venv = os.path.join(a.work, "venv")
    shutil.rmtree(venv, ignore_errors=True)
    os.makedirs(a.work, exist_ok=True)
    # Debian's python3-venv may lack ensurepip's wheels: Debian's pip (visible through
    # --system-site-packages) installs into the venv just as well.
    run([sys.executable, "-m", "venv", "--system-site-packages", "--without-pip", venv])
    py = os.path.join(venv, "bin", "python")
    t0 = time.time()
    # The CMake build directory is kept under --work so that a re-run only re-links.
    run([py, "-m", "pip", "install", "--no-index", "--no-deps", "--quiet", a.source,
         "--config-settings", "singlestrip-prefix=" + a.prefix, "--config-settings", "build-dir=" + os.path.join(a.work, "cmake-build")],
        env={**os.environ, "PIP_DISABLE_PIP_VERSION_CHECK": "1"})
    print(f"pip install . took {time.time() - t0:.1f} s", flush=True)
    # The installed module, from outside the source tree, is the one imported.
    code = ("import singlestrip, numpy as np, sys; "
            "assert singlestrip.__file__.startswith(sys.prefix), singlestrip.__file__; "
            "V, F = singlestrip.read('builtin:genus2'); "
            "assert V.dtype == np.float64 and F.dtype == np.uint32 and V.shape[1] == 3 and F.shape[1] == 3; "
            "r = singlestrip.strip(V, F); assert singlestrip.verify(V, F, r)['ok']; "
            "print('installed module OK:', singlestrip.__file__, len(r['strip']), 'indices')")
    run([py, "-c", code], cwd=a.work)
    run([py, "-m", "pytest", "-q", "-p", "no:cacheprovider", os.path.join(a.source, "tests", "python")], cwd=a.work)


if __name__ == "__main__":
    main()
