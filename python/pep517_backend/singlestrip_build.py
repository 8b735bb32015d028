"""PEP 517 build backend of the `singlestrip` Python package: CMake builds the module, this file
packs it into a wheel.

Why not scikit-build-core: it is not packaged for Debian 12 and the machines this project runs on
reach Debian's archive but not the Python package index. This backend needs nothing but CMake, a
C++ compiler and the Debian packages the project already uses (python3-dev, python3-pybind11),
so `pip install .` works offline, with or without build isolation (build-system.requires is empty).

Config settings (pip install . --config-settings key=value; -C with pip >= 23.1):
  singlestrip-prefix=DIR  build only the module, against the singlestrip installed in DIR
                          (cmake --install); default: build the library from this source tree too.
  build-dir=DIR           keep the CMake build directory there (incremental re-installs);
                          default: a temporary directory.
  build-type=TYPE         CMAKE_BUILD_TYPE (default Release).
  jobs=N                  parallel build jobs (default: CMAKE_BUILD_PARALLEL_LEVEL, else 2).
The environment variable SINGLESTRIP_PREFIX is the same as singlestrip-prefix.
"""
import base64
import hashlib
import os
import shutil
import subprocess
import sys
import sysconfig
import tarfile
import tempfile
import zipfile

NAME = "singlestrip"
SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _version():
    """The project version from the top-level CMakeLists.txt (one source of truth)."""
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as f:
        for line in f:
            if line.startswith("project(singlestrip VERSION"):
                return line.split("VERSION")[1].split()[0]
    raise RuntimeError("singlestrip_build: no version in CMakeLists.txt")


def _metadata():
    with open(os.path.join(SOURCE, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    return (
        "Metadata-Version: 2.1\n"
        f"Name: {NAME}\nVersion: {_version()}\n"
        "Summary: One triangle strip for any triangulated surface (C++ core, numpy in and out)\n"
        "License: see the repository\nRequires-Python: >=3.8\nRequires-Dist: numpy\n"
        "Description-Content-Type: text/markdown\n\n" + readme
    )


def _tag():
    """cpXY-cpXY<abiflags>-<platform>: the module is built for this interpreter only."""
    impl = f"cp{sys.version_info.major}{sys.version_info.minor}"
    plat = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{impl}-{impl}{getattr(sys, 'abiflags', '')}-{plat}"


def _setting(config_settings, key, env=None, default=None):
    value = (config_settings or {}).get(key)
    if value is None and env:
        value = os.environ.get(env)
    return value if value not in (None, "") else default


def _run(cmd):
    print("singlestrip_build:", " ".join(cmd), file=sys.stderr, flush=True)
    subprocess.run(cmd, check=True, stdout=sys.stderr)


def _build_module(config_settings, build_dir, stage):
    """Configures, builds and installs (component python) the module into `stage`."""
    prefix = _setting(config_settings, "singlestrip-prefix", "SINGLESTRIP_PREFIX")
    jobs = _setting(config_settings, "jobs", "CMAKE_BUILD_PARALLEL_LEVEL", "2")
    args = ["-DCMAKE_BUILD_TYPE=" + _setting(config_settings, "build-type", default="Release"),
            "-DPython_EXECUTABLE=" + sys.executable, "-DSINGLESTRIP_PYTHON_INSTALL_DIR=."]
    if prefix:  # only python/, against an installed library
        source = os.path.join(SOURCE, "python")
        args.append("-DCMAKE_PREFIX_PATH=" + os.path.abspath(prefix))
    else:
        source = SOURCE
        args += ["-DSINGLESTRIP_BUILD_PYTHON=ON", "-DSINGLESTRIP_BUILD_TESTS=OFF", "-DSINGLESTRIP_BUILD_RENDER=OFF"]
    generator = ["-G", "Ninja"] if shutil.which("ninja") and not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")) else []
    _run(["cmake", "-S", source, "-B", build_dir] + generator + args)
    _run(["cmake", "--build", build_dir, "--target", "singlestrip_python", "-j", str(jobs)])
    _run(["cmake", "--install", build_dir, "--component", "python", "--prefix", stage])
    modules = [f for f in os.listdir(stage) if f.startswith(NAME) and f.endswith((".so", ".pyd"))]
    if len(modules) != 1:
        raise RuntimeError(f"singlestrip_build: expected one built module in {stage}, found {modules}")
    return os.path.join(stage, modules[0])


def _record_line(arcname, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{arcname},sha256={digest},{len(data)}"


def _write_wheel(wheel_directory, module_path):
    dist_info = f"{NAME}-{_version()}.dist-info"
    name = f"{NAME}-{_version()}-{_tag()}.whl"
    with open(module_path, "rb") as f:
        files = {os.path.basename(module_path): f.read()}
    files[f"{dist_info}/METADATA"] = _metadata().encode()
    files[f"{dist_info}/WHEEL"] = (f"Wheel-Version: 1.0\nGenerator: singlestrip_build\nRoot-Is-Purelib: false\nTag: {_tag()}\n").encode()
    files[f"{dist_info}/top_level.txt"] = (NAME + "\n").encode()
    record = [_record_line(k, v) for k, v in files.items()] + [f"{dist_info}/RECORD,,"]
    files[f"{dist_info}/RECORD"] = ("\n".join(record) + "\n").encode()
    with zipfile.ZipFile(os.path.join(wheel_directory, name), "w", zipfile.ZIP_DEFLATED) as z:
        for arcname, data in files.items():
            z.writestr(arcname, data)
    return name


# PEP 517 hooks.

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    """Without this hook pip would build the whole wheel once just to read its metadata."""
    dist_info = f"{NAME}-{_version()}.dist-info"
    os.makedirs(os.path.join(metadata_directory, dist_info), exist_ok=True)
    with open(os.path.join(metadata_directory, dist_info, "METADATA"), "w", encoding="utf-8") as f:
        f.write(_metadata())
    return dist_info


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    build_dir = _setting(config_settings, "build-dir")
    with tempfile.TemporaryDirectory(prefix="singlestrip-wheel-") as tmp:
        build = os.path.abspath(build_dir) if build_dir else os.path.join(tmp, "build")
        module = _build_module(config_settings, build, os.path.join(tmp, "stage"))
        return _write_wheel(wheel_directory, module)


def build_sdist(sdist_directory, config_settings=None):
    """The sources the wheel needs (library, module, build files), as name-version.tar.gz."""
    base = f"{NAME}-{_version()}"
    keep = ["CMakeLists.txt", "pyproject.toml", "README.md", "cmake", "include", "src", "python"]
    name = base + ".tar.gz"
    with tarfile.open(os.path.join(sdist_directory, name), "w:gz") as tar:
        for item in keep:
            tar.add(os.path.join(SOURCE, item), arcname=f"{base}/{item}",
                    filter=lambda t: None if "__pycache__" in t.name else t)
        info = tarfile.TarInfo(f"{base}/PKG-INFO")
        data = _metadata().encode()
        info.size = len(data)
        tar.addfile(info, fileobj=__import__("io").BytesIO(data))
    return name
