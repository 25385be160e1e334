#!/bin/sh
# Install the Debian packages glscene needs, only those that are missing.
# Run by `make deps` (and so by `make demo` and `make test`).  Needs root.
set -e
PKGS="build-essential clang libclang-rt-14-dev valgrind bc re2c lemon libzstd-dev zlib1g-dev libosmesa6-dev libegl-dev pkg-config libstb-dev libjpeg62-turbo-dev libpng-dev libspng-dev python3-opencv parallel groff-base python3-venv python3-pip python3-setuptools python3-wheel"
missing=""
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "deps: installing$missing"
if [ "$(id -u)" != 0 ]; then
    echo "deps: not root; run as root: apt-get install$missing" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends $missing >/dev/null
