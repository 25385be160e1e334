#!/bin/sh
# sanitizers: not rerun (it checks the sources, the docs or the build, and runs no tool on an input)
# No switch of a test is read from the environment on a production path
# (issue 27 item 5): the tools' and the library's code (base, format,
# compiler, runtime, lib, apps, roads) reads only the variables a user sets
# on purpose, each listed below with why.  A test drives its own choices
# through the API instead: each band of a rolling shutter drawn whole
# (gls_play_opts' bands_whole, tools/glsplay_bands_whole.c for
# rolling_bands.sh), the sensor's number of threads (gls_sensor_apply's
# threads, tests/unit/test_sensor.c).  A new getenv fails here until it is
# listed, or goes.  Prints "ok NAME" / "FAIL NAME: why".
. tests/e2e/lib.sh
# FILE<tab>the code that reads the environment: why it is the user's
cat >"$t/allowed" <<'LIST'
compiler/roots.c	const char *env = getenv("GLSCENE_PATH");
lib/glscene_play_args.c	if (gls_shard_parse(next, getenv, &r->o.shard, msg, sizeof msg))
LIST
# GLSCENE_PATH: glsc's search path for imports (spec/language.md);
# glscene_play_args.c: --shard slurm reads SLURM_ARRAY_TASK_* (runtime/play/shard.h)

# every use of getenv, secure_getenv or environ outside comments, as
# FILE<tab>code (no line numbers, so that moving code needs no edit here)
grep -rnE '\b(secure_)?getenv\b|\benviron\b' base format compiler runtime lib apps roads include |
    grep -vE '^[^:]*:[0-9]+:[[:space:]]*(\*|/\*|//)' |
    sed -E 's/^([^:]*):[0-9]+:[[:space:]]*/\1\t/' | sort >"$t/found"
sort "$t/allowed" >"$t/allowed.sorted"
extra=$(comm -23 "$t/found" "$t/allowed.sorted" | tr '\t' ' ' | tr '\n' ';')
if [ -z "$extra" ]; then
    ok env_switches_none_on_production_paths
else
    fail env_switches_none_on_production_paths "reads the environment (a test's switch? drive it through the API; a user's setting? list it here with why):$extra"
fi
# the list is still true: each listed use is there (a stale line would
# let a new use of the same text through unseen)
gone=$(comm -13 "$t/found" "$t/allowed.sorted" | tr '\t' ' ' | tr '\n' ';')
if [ -z "$gone" ]; then
    ok env_switches_list_current
else
    fail env_switches_list_current "listed but not found (remove from the list):$gone"
fi
