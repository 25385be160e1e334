#!/bin/sh
# The README's gallery rows of camera effects, halved to 320x240 into DIR.
# Run by make gallery.  usage: gallery.sh BIN DIR
#
# Exposure (spec/camera.md "Motion blur, rolling shutter, depth of
# field"): the demo's left camera on a rig, frame 1, --aa 2, into
# DIR/effects_{blur,rolling,dof}.png.
#   motion blur:     driving forward 0.5 m a frame (traj.txt), shutter 1
#   rolling shutter: panning 4 degrees a frame (pan.txt), line_delay 1/480
#                    (the readout takes 0.96 frame intervals)
#   depth of field:  aperture 0.1 m, focus 6 m
# Lens and light (spec/camera.md "Lens distortion", "Shadows"): the demo's
# left camera (examples/demo/left.cam), frame 0, --aa 2, into
# DIR/effects_{distortion,fisheye,shadows}.png.
#   distortion:      Brown-Conrady k1 = -0.3 (bench/effects/distortion.keys)
#   fisheye:         an equisolid-angle fisheye, f = 350 px, 109 degrees
#                    across (bench/effects/fisheye.keys)
#   shadows:         the demo under a sun casting shadows through a 2048 x
#                    2048 map and a sky (bench/effects/DemoShadows.scene)
#   point shadows:   the demo at night under a street lamp casting shadows
#                    through a cube map (bench/effects/DemoPointShadows.scene),
#                    into DIR/effects_point_shadows.png
# The lens cases are make bench-effects' own keys files (bench/effects.cases).
set -e
B=$1 DIR=$2 H=bench/effects_o9
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
"$B/glsc" -I examples/demo -I "$B/textures" examples/demo/Demo.scene -o "$t/demo.glsb" 2>/dev/null
rig='width 640\nheight 480\nfx 600\nfy 600\ncx 319.5\ncy 239.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 500\npose rig\n'
printf "${rig}shutter 1\nexposure_samples 32\n" >"$t/blur.cam"
printf "${rig}line_delay 0.002\n" >"$t/rolling.cam"
printf "${rig}aperture 0.1\nfocus 6\nexposure_samples 64\n" >"$t/dof.cam"
for c in blur:traj rolling:pan dof:traj; do
    cam=${c%%:*} traj=${c#*:}
    "$B/glsplay" "$t/demo.glsb" --camera "$t/$cam.cam" --trajectory "$H/$traj.txt" --frames 1 --aa 2 \
        --outputs image -o "$t/out"
    "$B/pnghalf" "$t/out/$cam/image_000001.png" "$DIR/effects_$cam.png"
done
for lens in distortion fisheye; do
    sh bench/effects/with_keys.sh examples/demo/left.cam "bench/effects/$lens.keys" >"$t/$lens.cam"
    "$B/glsplay" "$t/demo.glsb" --camera "$t/$lens.cam" --aa 2 --background 0.55,0.7,0.9 --outputs image -o "$t/out"
    "$B/pnghalf" "$t/out/$lens/image_000000.png" "$DIR/effects_$lens.png"
done
"$B/glsc" -I examples/demo -I "$B/textures" -I bench/effects bench/effects/DemoShadows.scene -o "$t/shadows.glsb" 2>/dev/null
cp examples/demo/left.cam "$t/shadows.cam"
"$B/glsplay" "$t/shadows.glsb" --camera "$t/shadows.cam" --aa 2 --background 0.55,0.7,0.9 --outputs image -o "$t/out"
"$B/pnghalf" "$t/out/shadows/image_000000.png" "$DIR/effects_shadows.png"
"$B/glsc" -I examples/demo -I "$B/textures" -I bench/effects bench/effects/DemoPointShadows.scene \
    -o "$t/point_shadows.glsb" 2>/dev/null
cp examples/demo/left.cam "$t/point_shadows.cam"
"$B/glsplay" "$t/point_shadows.glsb" --camera "$t/point_shadows.cam" --aa 2 --background 0.02,0.02,0.05 \
    --outputs image -o "$t/out"
"$B/pnghalf" "$t/out/point_shadows/image_000000.png" "$DIR/effects_point_shadows.png"
