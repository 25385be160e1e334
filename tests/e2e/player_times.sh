#!/bin/sh
# glsplay --times (runtime/play/play_times.h): the run's time line, one
# line on stderr at its end, and nothing else changes: the same files,
# byte for byte, the same stdout, and --explain's plan without a clock in
# it.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
PLAY=$B/glsplay
[ -x "$PLAY" ] || { fail player_times "no $PLAY"; exit 0; }
$B/tests/test_player --write "$t" >/dev/null || { fail player_times "cannot write test scenes"; exit 0; }
pat='^glsplay: times: load [0-9.]* s, build [0-9.]* s (pack [0-9.]* s), context [0-9.]* s, upload [0-9.]* s, plan [0-9.]* s, first draw [0-9.]* s, write [0-9.]* s; total [0-9.]* s$'
"$PLAY" "$t/proj.glsb" --camera "$t/proj.cam" --outputs image,depth --aa 2 -o "$t/a" >"$t/a.out" 2>"$t/a.err"
ra=$?
"$PLAY" "$t/proj.glsb" --camera "$t/proj.cam" --outputs image,depth --aa 2 -o "$t/b" --times >"$t/b.out" 2>"$t/b.err"
rb=$?
if [ $ra -eq 0 ] && [ $rb -eq 0 ] && [ ! -s "$t/a.err" ] && [ "$(wc -l <"$t/b.err")" -eq 1 ] && grep -q "$pat" "$t/b.err"; then
    ok times_line
else
    fail times_line "exit $ra, $rb; stderr without: $(cat "$t/a.err"); with: $(cat "$t/b.err")"
fi
same=1
for f in image_000000.png depth_000000.pfm; do
    [ -s "$t/a/proj/$f" ] && cmp -s "$t/a/proj/$f" "$t/b/proj/$f" || same=0
done
if [ $same -eq 1 ] && cmp -s "$t/a.out" "$t/b.out"; then ok times_same_outputs
else fail times_same_outputs "the files or stdout differ with --times"; fi
# --explain is the same with --times: the time line is never in the plan
"$PLAY" "$t/proj.glsb" --camera "$t/proj.cam" --explain >"$t/e1" 2>&1
"$PLAY" "$t/proj.glsb" --camera "$t/proj.cam" --explain --times >"$t/e2" 2>&1
if [ -s "$t/e1" ] && cmp -s "$t/e1" "$t/e2" && ! grep -q 'times:' "$t/e2"; then ok times_not_in_explain
else fail times_not_in_explain "--explain's text differs with --times"; fi
# a failed run prints its error, not a time line
"$PLAY" "$t/proj.glsb" --camera "$t/nonexistent.cam" -o "$t/c" --times >/dev/null 2>"$t/c.err"
if [ $? -eq 1 ] && ! grep -q 'times:' "$t/c.err"; then ok times_not_on_failure
else fail times_not_on_failure "$(cat "$t/c.err")"; fi
