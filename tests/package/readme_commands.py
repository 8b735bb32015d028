"""ctest readme_commands: runs every `console` and `python` block of README.md.

console blocks: each line starting with "$ " (with "\\" continuation lines) is a shell command run
with bash -o pipefail; it must exit 0 (or 141, SIGPIPE, when `| head` stops reading), and each following line up to the next command is expected
output: the text before a "..." must appear in what the command printed (stdout and stderr).
A command that runs `singlestrip render` is skipped (with a message) when singlestrip-render was
not built. python blocks run with the module on PYTHONPATH.
Commands run in a scratch directory holding a copy of the repository's examples/, with the
built `singlestrip` first on PATH.

usage: readme_commands.py --readme README.md --bin <dir of singlestrip> [--python-path DIR]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile


def blocks(text, lang):
    return re.findall(r"^```" + lang + r"\n(.*?)^```", text, flags=re.S | re.M)


def console_commands(block):
    """[(command, [expected lines])] of one console block."""
    out, lines, i = [], block.splitlines(), 0
    while i < len(lines):
        line = lines[i]
        i += 1
        if not line.startswith("$ "):
            if out:
                out[-1][1].append(line)
            continue
        cmd = line[2:]
        while cmd.endswith("\\") and i < len(lines):
            cmd = cmd[:-1] + " " + lines[i].strip()
            i += 1
        out.append((cmd, []))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--readme", required=True)
    ap.add_argument("--bin", required=True)
    ap.add_argument("--python-path")
    a = ap.parse_args()
    with open(a.readme, encoding="utf-8") as f:
        text = f.read()
    source = os.path.dirname(os.path.abspath(a.readme))
    env = dict(os.environ, PATH=os.path.abspath(a.bin) + os.pathsep + os.environ.get("PATH", ""))
    if a.python_path:
        env["PYTHONPATH"] = os.path.abspath(a.python_path)
    render = os.path.exists(os.path.join(a.bin, "singlestrip-render"))
    failures, ran = [], 0
    with tempfile.TemporaryDirectory(prefix="singlestrip-readme-") as work:
        shutil.copytree(os.path.join(source, "examples"), os.path.join(work, "examples"))
        for block in blocks(text, "console"):
            for cmd, expected in console_commands(block):
                if "singlestrip render" in cmd and not render:
                    print(f"SKIP (render not built): {cmd}")
                    continue
                r = subprocess.run(["bash", "-o", "pipefail", "-c", cmd], cwd=work, env=env, capture_output=True, text=True)
                ran += 1
                output = r.stdout + r.stderr
                print(f"$ {cmd}\n{output}", end="" if output.endswith("\n") else "\n")
                # 141: SIGPIPE, when a reader such as `head` stops reading early (by design).
                if r.returncode not in (0, 141):
                    failures.append(f"{cmd}: exit {r.returncode}")
                for want in expected:
                    want = want.split("...")[0].strip()
                    if want and want not in output:
                        failures.append(f"{cmd}: output lacks {want!r}")
        if a.python_path is not None:
            for code in blocks(text, "python"):
                r = subprocess.run([sys.executable, "-c", code], cwd=work, env=env, capture_output=True, text=True)
                ran += 1
                print(f">>> python block\n{r.stdout}{r.stderr}")
                if r.returncode != 0:
                    failures.append(f"python block: exit {r.returncode}: {r.stderr.strip().splitlines()[-1:]}")
    for f in failures:
        print("FAILED:", f)
    print(f"README commands: {ran} run, {len(failures)} failed")
    return 1 if failures or ran == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
