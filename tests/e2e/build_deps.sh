#!/bin/sh
# suite: long (tests/run.sh starts it first, so that it does not run alone at the end)
# sanitizers: not rerun (it checks the sources, the docs or the build, and runs no tool on an input)
# Dependency tracking of the build: for every header of the tree (and the
# lexer and grammar sources), `make -n -W HEADER` must recompile exactly the
# sources that include it, directly or through other headers: objects,
# generated lexer and grammar, unit tests, benchmarks and tools alike.
# What includes what is found here independently of make's .d files: each
# compile command of `make -n -B` gives a source and its -I paths, and the
# #include "..." lines are followed as the compiler follows them (the
# includer's directory, then the -I paths in order).  Prints "ok NAME" /
# "FAIL NAME: why"; needs a complete build in $GLS_BIN (make all units
# programs); what is out of date before anything is touched is not judged.
# BUILD_DEPS_TARGETS overrides the make targets (default: all units
# programs).
. tests/e2e/lib.sh
[ -x $PY ] || { echo "FAIL build_deps: no $PY"; exit 0; }
command -v make >/dev/null || { echo "FAIL build_deps: no make"; exit 0; }
$PY - "$B" ${BUILD_DEPS_TARGETS:-all units programs} <<'PYEOF'
import os, re, shlex, subprocess, sys

B = sys.argv[1]
TARGETS = sys.argv[2:]


def make_n(*extra):
    p = subprocess.run(["make", "--no-print-directory", "-n", "B=" + B] + list(extra) + TARGETS,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if p.returncode:
        print("FAIL build_deps: make -n %s failed: %s" % (" ".join(extra + tuple(TARGETS)), p.stderr.strip()[-300:]))
        sys.exit(0)
    return p.stdout


def compiles(text):
    """{source: [-I dirs]} of the C compile commands in make -n output."""
    out = {}
    for line in text.splitlines():
        try:
            words = shlex.split(line)
        except ValueError:
            continue
        srcs = [w for w in words if w.endswith(".c")]
        if not words or not srcs or "-o" not in words:
            continue
        inc, i = [], 0
        while i < len(words):
            w = words[i]
            if w == "-I" and i + 1 < len(words):
                inc.append(words[i + 1])
                i += 1
            elif w.startswith("-I"):
                inc.append(w[2:])
            i += 1
        out[os.path.normpath(srcs[0])] = inc
    return out


every = compiles(make_n("-B"))
if not every:
    print("FAIL build_deps: make -n -B shows no compile command")
    sys.exit(0)
before = set(compiles(make_n()))

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
cache = {}


def includes(path, inc):
    """The headers path includes, resolved as the compiler does."""
    key = (path, tuple(inc))
    if key in cache:
        return cache[key]
    found = []
    try:
        text = open(path, errors="replace").read()
    except OSError:
        text = ""
    for name in INCLUDE.findall(text):
        for d in [os.path.dirname(path) or "."] + inc:
            cand = os.path.normpath(os.path.join(d, name))
            if os.path.isfile(cand):
                found.append(cand)
                break
    cache[key] = found
    return found


def closure(src, inc):
    seen, todo = set(), [src]
    while todo:
        for h in includes(todo.pop(), inc):
            if h not in seen:
                seen.add(h)
                todo.append(h)
    return seen


deps = {src: closure(src, inc) for src, inc in every.items()}
headers = sorted({h for s in deps.values() for h in s if not h.startswith("/")})
bad = 0
for h in headers:
    want = {s for s, hs in deps.items() if h in hs} - before
    got = set(compiles(make_n("-W", h))) - before
    if want == got:
        print("ok build_deps_%s" % h.replace("/", "_"))
    else:
        bad += 1
        print("FAIL build_deps_%s: touching it recompiles %d of the %d sources that include it; not rebuilt: %s; "
              "rebuilt though it does not include it: %s" % (
                  h.replace("/", "_"), len(want & got), len(want), " ".join(sorted(want - got)) or "none",
                  " ".join(sorted(got - want)) or "none"))
# the generated sources: a changed lexer.re or grammar.y regenerates and
# recompiles them
for gen, src in (("compiler/lexer.re", "gen/lexer.c"), ("compiler/grammar.y", "gen/grammar.c")):
    got = compiles(make_n("-W", gen))
    name = "build_deps_" + gen.replace("/", "_")
    if os.path.normpath(os.path.join(B, src)) in got:
        print("ok " + name)
    else:
        print("FAIL %s: touching it does not recompile %s/%s" % (name, B, src))
# lemon writes grammar.c and grammar.h in one run: under -j the recipe
# must run once (two copies raced on gen/grammar.y and failed a CI build)
p = subprocess.run(["make", "--no-print-directory", "-n", "-j2", "-W", "compiler/grammar.y", "B=" + B,
                    os.path.join(B, "gen/grammar.c"), os.path.join(B, "gen/grammar.h")],
                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
runs = sum(1 for line in p.stdout.splitlines() if line.lstrip().startswith("cd ") and "lemon" in line)
if p.returncode == 0 and runs == 1:
    print("ok build_deps_grammar_made_once")
else:
    print("FAIL build_deps_grammar_made_once: make -n -j2 runs lemon %d times (rc %d)" % (runs, p.returncode))
if before:
    print("note: build_deps: out of date before the test, not judged: %s" % " ".join(sorted(before)))
PYEOF
