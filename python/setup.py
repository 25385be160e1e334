"""Installs the Python binding (python/glscene) with its library beside it,
offline, as Debian users install (README "Use it from Python"):

    python3 -m venv --system-site-packages ENV
    ENV/bin/pip install --no-index --no-build-isolation .          # or ./python

Building the package runs the repository's make for libglscene.so (make
decides what to rebuild: nothing when build/ is up to date, so the
library of a built checkout is the one bundled) and copies
libglscene.so.MAJOR into the package, where glscene/__init__.py looks
first.  The repository's setup.py runs this file; setuptools, wheel and
numpy are Debian's (python3-setuptools, python3-wheel, python3-numpy),
reached through --system-site-packages.  tests/e2e/python_package.sh does
both installs in a temporary venv and renders."""
import os
import re
import shutil
import subprocess

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
# the build directory make writes (the Makefile's B, relative to the
# repository or absolute); GLSCENE_BUILD names another one, as GLS_BIN
# does for the tests
B = os.environ.get("GLSCENE_BUILD") or "build"
BUILD = os.path.join(REPO, B)


def version():
    """include/glscene.h's GLSCENE_VERSION, as the Makefile reads it."""
    with open(os.path.join(REPO, "include", "glscene.h")) as f:
        m = re.search(r'^#define GLSCENE_VERSION "(.*)"$', f.read(), re.M)
    if not m:
        raise SystemExit("glscene: error: no GLSCENE_VERSION in include/glscene.h")
    return m.group(1)


SONAME = "libglscene.so." + version().split(".")[0]


class BuildWithLibrary(build_py):
    """build_py, then make's libglscene.so.MAJOR copied into the package."""

    def run(self):
        super().run()
        cmd = ["make", "-C", REPO, "--no-print-directory", "B=" + B, B + "/libglscene.so"]
        # a make above (make test) passes its jobserver in MAKEFLAGS; this
        # make is a command of its own
        env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
        if subprocess.call(cmd, env=env) != 0:
            raise SystemExit("glscene: error: '%s' failed: libglscene did not build "
                             "(the Debian packages it needs: sh tools/deps.sh)" % " ".join(cmd))
        dest = os.path.join(self.build_lib, "glscene")
        os.makedirs(dest, exist_ok=True)
        # the file itself, not the link to it
        shutil.copyfile(os.path.join(BUILD, SONAME), os.path.join(dest, SONAME))
        os.chmod(os.path.join(dest, SONAME), 0o755)


class BinaryDistribution(Distribution):
    """The wheel holds a compiled library: it is for this platform only."""

    def has_ext_modules(self):
        return True


# setuptools' own build files and metadata go under the build directory
# (git ignores it), not into the checkout
rel = lambda p: os.path.relpath(p, os.getcwd())
os.makedirs(os.path.join(BUILD, "python"), exist_ok=True)
setup(
    name="glscene",
    version=version(),
    description="Synthetic images with an exact answer key for computer-vision tests (ctypes binding over libglscene)",
    license="see the repository",
    packages=["glscene"],
    package_dir={"glscene": rel(os.path.join(HERE, "glscene"))},
    python_requires=">=3.9",
    install_requires=["numpy"],
    cmdclass={"build_py": BuildWithLibrary},
    distclass=BinaryDistribution,
    options={"build": {"build_base": rel(os.path.join(BUILD, "python"))},
             "egg_info": {"egg_base": rel(os.path.join(BUILD, "python"))}},
    zip_safe=False,
)
