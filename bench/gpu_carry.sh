#!/bin/sh
# make bench-gpu on a machine that has a GPU but not this project's build
# (a lent GPU machine: no Debian packages, no network).  How the figures
# in docs/benchmarks.md "GPU" were made.
#
# usage: bench/gpu_carry.sh pack DIR
#            here (Debian 12): build glsplay with EGL only (GLS_NO_OSMESA=1,
#            in build-gpu), then put into DIR the tools, the bench programs,
#            scenelib and textures, the shared libraries the tools need
#            beyond libc (glvnd's libEGL and libGLdispatch from Debian's
#            libegl1 and libglvnd0, libzstd, libspng, libjpeg, zlib) and
#            bench/gpu.sh's inputs
#        bench/gpu_carry.sh run DIR OUTDIR
#            there, from a copy of this checkout: NVIDIA's EGL vendor found
#            and named, the exactness tests that check glsplay against
#            independent computations (GLS_PY: that machine's python3 with
#            numpy and cv2), then bench/gpu.sh run; logs in OUTDIR
set -e
cmd=$1 DIR=$2
case $cmd in
pack)
    [ -n "$DIR" ] || { echo "usage: bench/gpu_carry.sh pack DIR" >&2; exit 2; }
    GLS_NO_OSMESA=1 make -s -j2 B=build-gpu all programs
    mkdir -p "$DIR/bin/bench" "$DIR/lib"
    cp build-gpu/glsplay build-gpu/glsc build-gpu/glsdis build-gpu/glsroad build-gpu/depth2png build-gpu/distort_project "$DIR/bin/"
    cp build-gpu/bench/instances_bench build-gpu/bench/play_bench build-gpu/bench/play_floor "$DIR/bin/bench/"
    rm -rf "$DIR/bin/scenelib.glsb" "$DIR/bin/textures"
    cp -r build-gpu/scenelib.glsb build-gpu/textures "$DIR/bin/"
    t=$(mktemp -d)
    (cd "$t" && apt-get download libegl1 libglvnd0 >/dev/null)
    for f in "$t"/*.deb; do dpkg -x "$f" "$t/x"; done
    cp -L "$t"/x/usr/lib/x86_64-linux-gnu/libEGL.so.1 "$t"/x/usr/lib/x86_64-linux-gnu/libGLdispatch.so.0 "$DIR/lib/"
    rm -rf "$t"
    for l in libzstd.so.1 libspng.so.0 libz.so.1 libjpeg.so.62; do cp -L "/lib/x86_64-linux-gnu/$l" "$DIR/lib/"; done
    rm -rf "$DIR/in"
    sh bench/gpu.sh prepare "$DIR/bin" "$DIR/in" >/dev/null
    ;;
run)
    OUT=$3
    [ -n "$DIR" ] && [ -n "$OUT" ] || { echo "usage: bench/gpu_carry.sh run DIR OUTDIR" >&2; exit 2; }
    G=$(cd "$DIR" && pwd)
    mkdir -p "$OUT"
    vend=$(ls /usr/local/nvidia/share/glvnd/egl_vendor.d/*.json /usr/share/glvnd/egl_vendor.d/*nvidia*.json 2>/dev/null | head -1)
    nvlib=$(dirname "$(find / -xdev -name 'libEGL_nvidia.so.0' 2>/dev/null | head -1)")
    export __EGL_VENDOR_LIBRARY_FILENAMES="$vend"
    export LD_LIBRARY_PATH="$G/lib:$nvlib:/usr/local/nvidia/lib64:$LD_LIBRARY_PATH"
    "$G/bin/glsplay" "$G/in/random.glsb" --camera "$G/in/cam_640.cam" --explain 2>&1 | grep -i 'backend\|GL_RENDERER' | tee "$OUT/env.txt"
    grep -q 'GL_RENDERER.*NVIDIA' "$OUT/env.txt" || { echo "bench/gpu_carry.sh: no NVIDIA GL renderer" >&2; exit 1; }
    for s in ground_truth camera_pose landmarks outputs_disparity lens_truth outputs_flow outputs_boxes classes occlusion; do
        echo "# $s"
        GLS_BIN="$G/bin" GLS_PY=$(command -v python3) timeout 90 sh tests/e2e/$s.sh 2>&1 || true
    done >"$OUT/tests.txt"
    echo "tests: $(grep -c '^ok' "$OUT/tests.txt") ok, $(grep -c '^FAIL' "$OUT/tests.txt") failed"
    grep '^FAIL' "$OUT/tests.txt" || true
    sh bench/gpu.sh run "$G/bin" "$G/in" egl "${FRAMES:-120}" | tee "$OUT/gpu.txt"
    ;;
*)
    echo "usage: bench/gpu_carry.sh pack DIR | run DIR OUTDIR" >&2
    exit 2
    ;;
esac
