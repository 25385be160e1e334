#!/bin/sh
# The Python package installs offline, as Debian users install
# (README "Use it from Python", python/setup.py): into a venv made with
# --system-site-packages (Debian's numpy, setuptools and wheel),
#     pip install --no-index --no-build-isolation .
#     pip install --no-index --no-build-isolation ./python
# each build libglscene with the repository's make (the second after the
# library is removed, so make links it again) and installs glscene with the
# library beside it; `import glscene` from another directory, without
# PYTHONPATH or GLSCENE_LIBRARY, loads that library and renders the demo.
# Works in a copy of the checkout (the files git tracks or would track,
# with $GLS_BIN as its build/, as tests/e2e/readme_commands.sh does) and
# checks that the installs leave it clean.  No network: --no-index.
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
# an ASan-built libglscene.so cannot be loaded into python (python_binding.sh)
[ "$GLS_SANITIZED" = 1 ] && exit 0
need python_package libglscene.so textures.stamp
command -v git >/dev/null || { fail python_package "no git"; exit 0; }
$PY -c 'import venv, ensurepip' 2>/dev/null || { fail python_package "no venv/ensurepip under $PY (Debian: python3-venv)"; exit 0; }
repo=$t/repo
mkdir "$repo"
git ls-files -z --cached --others --exclude-standard |
    tar --null -T - --ignore-failed-read -cf - 2>/dev/null | tar -xf - -C "$repo" || { fail python_package "tar"; exit 0; }
cp -a "$B/." "$repo/build/" || { fail python_package "cannot copy $B"; exit 0; }
rm -f "$repo/build/test.log"
(cd "$repo" && git init -q && git add -A && git -c user.name=t -c user.email=t@localhost commit -qm copy) ||
    { fail python_package "git"; exit 0; }
# what a user's shell has, not this suite's
unset MAKEFLAGS MFLAGS MAKELEVEL B GLS_BIN PYTHONPATH GLSCENE_LIBRARY
export PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_CACHE_DIR=1 PYTHONDONTWRITEBYTECODE=1
# pip sees what Debian gives and nothing this machine's pip settings add
# (a wheel directory, an index)
unset PIP_FIND_LINKS PIP_INDEX_URL PIP_EXTRA_INDEX_URL PIP_NO_INDEX
export PIP_CONFIG_FILE=/dev/null

# the render, run from a directory that is not the checkout
mkdir "$t/elsewhere"
cat >"$t/elsewhere/render.py" <<'EOF2'
import os, sys
import glscene
repo, venv = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(glscene.__file__))
assert here.startswith(os.path.realpath(venv)) or here.startswith(venv), here
lib = glscene._lib._name
assert os.path.dirname(os.path.abspath(lib)) == here, "library %s, not beside %s" % (lib, here)
glscene.compile(os.path.join(repo, "examples/demo/Demo.scene"),
                [os.path.join(repo, "examples/demo"), os.path.join(repo, "build/textures")], "demo.glsb")
player = glscene.Player("demo.glsb", aa=4, background=(0.55, 0.7, 0.9))
out = player.render(glscene.Camera.from_file(os.path.join(repo, "examples/demo/left.cam")), outputs=("image", "depth"))
print(out["image"].shape, out["depth"][460, 400], glscene.version())
EOF2
want="(480, 640, 3) 3.17011 $(sed -n 's/^#define GLSCENE_VERSION "\(.*\)"$/\1/p' include/glscene.h)"

# install SOURCE NAME: a new venv, pip install SOURCE (relative to the
# copy's root), then the render from elsewhere
install() {
    v=$t/venv_$2
    rm -rf "$v"
    $PY -m venv --system-site-packages "$v" >"$t/log" 2>&1 || { fail "$2" "venv: $(tail -3 "$t/log")"; return; }
    if ! (cd "$repo" && "$v/bin/pip" install --no-index --no-build-isolation "$1") >"$t/log" 2>&1; then
        fail "$2" "pip install $1: $(grep -i error "$t/log" | head -3 | tr '\n' ' ')"; return
    fi
    got=$(cd "$t/elsewhere" && "$v/bin/python" render.py "$repo" "$v" 2>&1)
    [ "$got" = "$want" ] && ok "$2" || fail "$2" "printed '$got', want '$want'"
    [ -z "$(cd "$repo" && git status --porcelain)" ] && ok "${2}_leaves_checkout_clean" ||
        fail "${2}_leaves_checkout_clean" "$(cd "$repo" && git status --porcelain | head -5 | tr '\n' ' ')"
}
install . python_package_root
# no library in build/: make links it again (its objects are there)
rm -f "$repo"/build/libglscene.so*
install ./python python_package_subdir
[ -f "$repo/build/libglscene.so.0" ] && ok python_package_builds_library ||
    fail python_package_builds_library "no build/libglscene.so.0 after pip install ./python"
# the README's install commands are the ones run above
grep -qxF '    python3 -m venv --system-site-packages ~/glscene-venv' README.md &&
    grep -qxF '    ~/glscene-venv/bin/pip install --no-index --no-build-isolation .' README.md &&
    ok python_package_readme_commands ||
    fail python_package_readme_commands "README.md no longer gives the venv and pip install commands this test runs"
