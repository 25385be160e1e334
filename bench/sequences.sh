# Sourced by the benches that time glsplay over sequences (backends.sh,
# encode.sh, scaling.sh): the inputs they share, written into the
# directory $t with the build $B:
#   road     examples/road/demo.road as glsroad writes it, compiled with
#            the scene library; ROAD: glsplay's arguments for it (left rig
#            camera, its trajectory, the demo's sky colour)
#   terrain  bench/play_scene.h's 100,352-triangle height field, its rig
#            camera and camera path (play_bench --write); TERRAIN likewise
# Exits the bench if any of them cannot be made.
"$B/glsroad" examples/road/demo.road -o "$t/road" >/dev/null &&
    "$B/glsc" -I "$B/scenelib.glsb" -I "$t/road" -o "$t/road.glsb" "$t/road/road.scene" &&
    "$B/bench/play_bench" --write "$t" || exit 1
ROAD="$t/road.glsb --camera examples/road/rig/left.cam --trajectory $t/road/trajectory.txt --background 0.55,0.7,0.9"
TERRAIN="$t/terrain.glsb --camera $t/rig.cam --trajectory $t/trajectory.txt"
