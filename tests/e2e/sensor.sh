#!/bin/sh
# suite: long (tests/run.sh starts it first, so that it does not run alone at the end)
# glsplay's sensor effects (spec/camera.md "Sensor effects"): the noise,
# vignetting and Bayer mosaic against the model in tests/py/check_sensor.py;
# --explain names each effect on, the key asking for it and its cost, and
# nothing for a camera without; the frame record names the effects, so
# --resume renders again a frame whose camera's sensor changed.  The
# keys' errors are in tests/errors/camera/sensor_*.cam (camera_errors.sh).
# Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
py_check sensor_check check_sensor.py "$BIN" "$t"

mkdir -p "$t/src" "$t/a"
printf 'color(0.5, 0.5, 0.5);\npoly { vert(-9, -9, 5); vert(9, -9, 5); vert(9, 9, 5); vert(-9, 9, 5); }\n' >"$t/src/W.scene"
"$BIN/glsc" -I "$t/src" -o "$t/w.glsb" W 2>"$t/err" || { fail sensor_setup "$(cat "$t/err")"; exit 0; }
cam='width 64\nheight 48\nfx 60\nfy 60\ncx 31.5\ncy 23.5\nR 1 0 0 0 1 0 0 0 1\nT 0 0 0\nnear 0.1\nfar 100\n'
printf "$cam" >"$t/plain.cam"
printf "${cam}vignetting poly -0.2 0 0\ngain 2\nshot_noise 400\nread_noise 0.004\nnoise_seed 3\nbayer BGGR\n" >"$t/a/left.cam"

# --explain: every effect on, in order, with its key and the cost
"$BIN/glsplay" "$t/w.glsb" --camera "$t/a/left.cam" --explain >"$t/plan" 2>"$t/err"
sed -n '/^  sensor/,/cost:/p' "$t/plan" >"$t/got"
cat >"$t/want" <<'END'
  sensor (camera file keys; applied to the image only, never to depth, points or other ground truth), in this order:
    vignetting poly ('vignetting poly -0.2 0 0'): times 1 + a1 r^2 + a2 r^4 + a3 r^6, r = distance to (cx, cy) / fx
    gain 2 ('gain')
    shot noise ('shot_noise 400'): Poisson photon counts, 400 electrons at intensity 1
    read noise ('read_noise 0.004'): Gaussian, sigma 0.004 of full scale
    noise seed 3 ('noise_seed'), keyed by camera name, frame and pixel
    clip to [0, 1], quantise
    bayer BGGR ('bayer BGGR'): the image is a one-channel mosaic
    cost: a post-process over 3072 pixels (no extra pass)
END
if cmp -s "$t/want" "$t/got"; then ok sensor_explain; else fail sensor_explain "$(diff "$t/want" "$t/got")"; fi
"$BIN/glsplay" "$t/w.glsb" --camera "$t/plain.cam" --explain >"$t/plan" 2>"$t/err"
if grep -q sensor "$t/plan"; then fail sensor_explain_none "a camera without sensor keys shows: $(grep sensor "$t/plan")"
else ok sensor_explain_none; fi
"$BIN/glsplay" "$t/w.glsb" --camera "$t/a/left.cam" --outputs depth --explain >"$t/plan" 2>"$t/err"
if grep -q '^  sensor: effects asked for by the camera file, not applied: no image is written' "$t/plan"; then
    ok sensor_explain_no_image
else
    fail sensor_explain_no_image "$(grep sensor "$t/plan")"
fi

# --resume: a frame whose camera's sensor changed is rendered again
"$BIN/glsplay" "$t/w.glsb" --camera "$t/a/left.cam" --outputs image -o "$t/out" 2>"$t/err" || fail sensor_resume "$(cat "$t/err")"
cp "$t/out/left/image_000000.png" "$t/first.png"
sed -i 's/noise_seed 3/noise_seed 4/' "$t/a/left.cam"
"$BIN/glsplay" "$t/w.glsb" --camera "$t/a/left.cam" --outputs image -o "$t/out" --resume 2>"$t/err"
if grep -q '0 of 1 frame complete' "$t/err" && ! cmp -s "$t/first.png" "$t/out/left/image_000000.png"; then
    ok sensor_resume_renders_changed_sensor
else
    fail sensor_resume_renders_changed_sensor "$(cat "$t/err")"
fi
"$BIN/glsplay" "$t/w.glsb" --camera "$t/a/left.cam" --outputs image -o "$t/out" --resume 2>"$t/err"
if grep -q '1 of 1 frame complete' "$t/err"; then ok sensor_resume_skips_same; else fail sensor_resume_skips_same "$(cat "$t/err")"; fi
