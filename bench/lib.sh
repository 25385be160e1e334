# What the benchmark scripts (make bench-*) share, once.  Each sources it
# from the repository root as `. bench/lib.sh`; it defines functions only
# and changes nothing until one is called.

# fixed_malloc: fixed malloc thresholds for every timed run.  llvmpipe
# allocates and frees large bin buffers every frame; with glibc's default
# adaptive mmap threshold a process can end up page-faulting them in anew
# each frame, which swamped the measurement (bench/play.sh's floor ran at a
# third of its speed).  Every program a bench times runs with these.
fixed_malloc() {
    export GLIBC_TUNABLES=glibc.malloc.trim_threshold=4000000000:glibc.malloc.mmap_threshold=33554432
}

# work_dir: t, a temporary directory removed on exit
work_dir() {
    t=$(mktemp -d) && trap 'rm -rf "$t"' EXIT || exit 1
}

# cpu: the processor's model name; machine: the machine line of the
# docs/benchmarks.md blocks (processor, cores, kernel)
cpu() { grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'; }
machine() { echo "$(cpu), $(nproc) cores, $(uname -sr)"; }

# loadavg N: the first N load averages (1, 5, 15 minutes)
loadavg() { cut -d' ' -f1-"$1" /proc/loadavg; }

# run_fps N COMMAND ARGS...: frames per second of one whole run of
# COMMAND ARGS --frames 0:N -o $t/out (a glsplay: start-up, upload and
# file writing included); if it fails, its errors and the bench ends
run_fps() {
    rf_n=$1
    shift
    rm -rf "$t/out"
    rf_t0=$(now)
    "$@" --frames "0:$rf_n" -o "$t/out" 2>"$t/err" || { cat "$t/err" >&2; exit 1; }
    rate "$rf_n" "$rf_t0" "$(now)"
}

# now: seconds since the epoch, to the nanosecond; rate N T0 T1: N per
# second from T0 to T1, two decimals; larger X Y: the larger number
now() { date +%s.%N; }
rate() { awk -v n="$1" -v a="$2" -v b="$3" 'BEGIN { printf "%.2f", n / (b - a) }'; }
larger() { awk -v x="$1" -v y="$2" 'BEGIN { print (x > y ? x : y) }'; }
