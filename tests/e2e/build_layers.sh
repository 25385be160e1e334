#!/bin/sh
# suite: long (tests/run.sh starts it first, so that it does not run alone at the end)
# sanitizers: not rerun (it checks the sources, the docs or the build, and runs no tool on an input)
# The layering is enforced by the build (docs/ARCHITECTURE.md, "Layers"):
# each layer's objects are compiled with the include paths of the layers it
# may see and no others, so a file that includes a header across the rule
# does not compile.  For every layer, the include paths are taken from the
# compile command make gives for one of its files (make -n -B), and a probe
# that includes every header of every layer directory is compiled with
# them: it must compile where the table below allows it, and fail with
# "No such file" where it does not.  Also: no source reaches into another
# directory with a relative include ("../x.h"), which would bypass the rule.
# Prints "ok NAME" / "FAIL NAME: why"; needs $GLS_BIN (default build)
# built, for the generated grammar.h.
. tests/e2e/lib.sh
CC=${CC:-cc}

# LAYER  a file of it  the directories it may see (gen: the compiler's
# generated grammar.h); glsroad is the glsroad tool's main, which also reads
# camera files and trajectories; lib is libglscene (docs/api.md), over the
# compiler and the runtime, with its public header in include/; glsplay is
# glsplay's main (apps/), which sees the public header and base only.  The
# runtime is rooms (runtime/ROOM, docs/ARCHITECTURE.md), each seeing the
# rooms before it: gl < scene < camera < render < aa < effects < truth <
# encode < write < play.
table='
base     base/buf.c                    base
format   format/insn.c                 format base
compiler compiler/unit.c               compiler gen format base
gl       runtime/gl/glcalls.c          gl format base
scene    runtime/scene/scene_pack.c    scene gl format base
camera   runtime/camera/camera.c       camera scene gl format base
render   runtime/render/render.c       render camera scene gl format base
aa       runtime/aa/aa.c               aa render camera scene gl format base
effects  runtime/effects/exposure.c    effects aa render camera scene gl format base
truth    runtime/truth/gt_flow.c       truth effects aa render camera scene gl format base
encode   runtime/encode/outputs.c      encode truth effects aa render camera scene gl format base
write    runtime/write/frame_files.c   write encode truth effects aa render camera scene gl format base
play     runtime/play/player.c         play write encode truth effects aa render camera scene gl format base
roads    roads/nurbs.c                 roads base
glsroad  roads/glsroad_main.c          roads camera scene gl format base
lib      lib/glscene.c                 lib include compiler gen play write encode truth effects aa render camera scene gl format base
glsplay  apps/glsplay_main.c           include base
'
rooms="gl scene camera render aa effects truth encode write play"
dirs="base format compiler gen $rooms roads lib include"
headers() { # DIR: the headers of a layer directory
    case $1 in
    gen) echo "$B/gen/grammar.h" ;;
    gl | scene | camera | render | aa | effects | truth | encode | write | play) ls runtime/"$1"/*.h ;;
    *) ls "$1"/*.h ;;
    esac
}

echo "$table" | while read -r layer file sees; do
    [ -n "$layer" ] || continue
    obj=$B/${file%.c}.o
    cmd=$(make --no-print-directory -n -B "B=$B" "$obj" 2>/dev/null | grep -F -- "-c $file ")
    if [ -z "$cmd" ]; then
        echo "FAIL build_layers_$layer: make -n -B $obj shows no compile of $file"
        continue
    fi
    inc=$(for w in $cmd; do case $w in -I*) printf '%s ' "$w" ;; esac; done)
    for d in $dirs; do
        : >"$t/probe.c"
        for h in $(headers "$d"); do printf '#include "%s"\n' "$(basename "$h")" >>"$t/probe.c"; done
        # shellcheck disable=SC2086
        $CC -std=c11 -D_XOPEN_SOURCE=700 -fsyntax-only $inc "$t/probe.c" >"$t/out" 2>&1
        rc=$?
        case " $sees " in
        *" $d "*)
            if [ $rc -eq 0 ]; then echo "ok build_layers_${layer}_sees_$d"
            else echo "FAIL build_layers_${layer}_sees_$d: $(grep -m1 error "$t/out") (include paths: $inc)"; fi ;;
        *)
            if [ $rc -ne 0 ] && grep -q 'No such file' "$t/out"; then echo "ok build_layers_${layer}_not_$d"
            else echo "FAIL build_layers_${layer}_not_$d: a $layer file can include $d's headers (include paths: $inc)"; fi ;;
        esac
    done
done

# no relative include reaches out of its directory
esc=$(grep -n '#[[:space:]]*include[[:space:]]*"\.\./' base/* format/* compiler/* runtime/*/* apps/* roads/* lib/* include/* \
      tests/unit/* tests/fuzz/*.c bench/* tools/*.c scenelib/gen/*.c 2>/dev/null | head -5)
if [ -z "$esc" ]; then echo "ok build_layers_no_relative_includes"
else echo "FAIL build_layers_no_relative_includes: $(echo "$esc" | tr '\n' ' ')"; fi
