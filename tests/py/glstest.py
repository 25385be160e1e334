"""What the Python checks share: the "ok NAME" / "FAIL NAME: why" lines
tests/run.sh counts, writing a file with its directories, and running a
tool (an exception with its message when it fails)."""
import os
import subprocess


def ok(name):
    print("ok " + name)


def fail(name, why):
    print("FAIL %s: %s" % (name, why))


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def run(*args):
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError("%s: exit %d: %s" % (args[0], r.returncode, r.stderr.strip()))
    return r.stdout
