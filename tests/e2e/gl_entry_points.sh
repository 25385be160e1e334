#!/bin/sh
# sanitizers: not rerun (it checks the sources, the docs or the build, and runs no tool on an input)
# The GL entry points beyond GL 1.1 are listed once (GLS_GLEXT in
# runtime/gl/glcalls.h) and loaded once, by the renderer (runtime/gl/glcalls.c):
# no other file of the runtime or the library names a glext.h PFN type or
# looks a function up itself, and every function of the list is called
# somewhere.  Prints "ok NAME" / "FAIL NAME: why".
own=$(grep -l 'PFNGL[A-Z0-9]*PROC' runtime/*/*.c runtime/*/*.h lib/*.c lib/*.h 2>/dev/null | grep -v '^runtime/gl/glcalls\.[ch]$' | tr '\n' ' ')
look=$(grep -l 'gls_glctx_proc(' runtime/*/*.c lib/*.c 2>/dev/null | grep -v '^runtime/gl/glcalls\.c$' | grep -v '^runtime/gl/glctx\.c$' | tr '\n' ' ')
if [ -z "$own$look" ]; then
    echo "ok gl_entry_points_one_list"
else
    echo "FAIL gl_entry_points_one_list: PFN types outside glcalls.h: ${own:-none}; own lookups: ${look:-none}"
fi
unused=""
for f in $(sed -n 's/.*X(PFNGL[A-Z0-9]*PROC, \(gl[A-Za-z0-9]*\)).*/\1/p' runtime/gl/glcalls.h); do
    grep -q "[.>]$f(" runtime/*/*.c || unused="$unused $f"
done
n=$(grep -c 'X(PFNGL[A-Z0-9]*PROC, gl' runtime/gl/glcalls.h)
if [ -z "$unused" ] && [ "$n" -gt 0 ]; then
    echo "ok gl_entry_points_all_called"
else
    echo "FAIL gl_entry_points_all_called: listed but never called:${unused:- (no list found)}"
fi
