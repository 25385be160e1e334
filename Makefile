# glscene build.  `make` builds the tools into build/; `make test` runs the
# test suite; `make demo` renders the demo.  Both install missing Debian
# packages first (tools/deps.sh).
CC      ?= cc
CSTD    := -std=c11 -D_XOPEN_SOURCE=700
WARN    := -Wall -Wextra -Werror
OPT     ?= -O2 -g
CFLAGS  += $(CSTD) $(WARN) $(OPT)
LDLIBS  := -lzstd -lz -ljpeg -lstb -lm
# Every compile writes its dependency file (X.d beside X, the object or
# program), included at the end: a changed header rebuilds exactly what
# includes it (tests/e2e/build_deps.sh).
DEPFLAGS := -MMD -MP

ifeq ($(SANITIZE),1)
CFLAGS  += -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
LDFLAGS += -fsanitize=address,undefined
endif

B ?= build

# FUZZ=1: libFuzzer coverage instrumentation plus ASan and UBSan (clang).
ifeq ($(FUZZ),1)
CFLAGS  += -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
# The fuzz build only: lower unroll limits.  A loop nest at the real limit
# (2^22 statements an object) runs about 10 s under this instrumentation,
# libFuzzer's timeout, so the fuzzer reported the language's own limit as a
# hang; the limit checks are the same code at any value.
CFLAGS  += -DGLS_MAX_UNROLLED='(1u << 16)' -DGLS_MAX_UNROLLED_TOTAL='(1ull << 20)'
LDFLAGS += -fsanitize=address,undefined
endif

# The layers (docs/ARCHITECTURE.md) and the headers each may include: its
# own and those of the layers below it, through these include paths only,
# so that a file including across the rule does not compile
# (tests/e2e/build_layers.sh).  Seeing a layer means seeing what it sees.
INC_base     := -Ibase
INC_format   := -Iformat $(INC_base)
INC_compiler := -Icompiler -I$(B)/gen $(INC_format)
# The runtime is rooms (docs/ARCHITECTURE.md "The runtime's rooms"), each a
# folder of runtime/ with one job, in this order; a room sees its own
# headers and those of the rooms before it, and no others
# (tests/e2e/build_layers.sh).  gl: GL context, backends, entry points,
# programs; scene: the bundle built into draw state; camera: camera
# models, files, lens maths, trajectories, motion; render: colour, depth
# and id passes, lighting, shadows, occlusion; aa: anti-aliasing; effects:
# sensor, exposure (motion blur, rolling shutter, depth of field), lens
# resampling; truth: ground truth (ids, classes, boxes, flow, landmarks,
# disparity); encode: file formats and the output vocabulary; write: the
# writer thread and a frame's files; play: the frame plan, the frame loop,
# explain, progress, frame records, calibration files.
RUNTIME_ROOMS := gl scene camera render aa effects truth encode write play
# $(B)/gen/runtime: glctx_backends.h, which GL backends this build has (below)
INC_rt_gl      := -Iruntime/gl -I$(B)/gen/runtime $(INC_format)
INC_rt_scene   := -Iruntime/scene $(INC_rt_gl)
INC_rt_camera  := -Iruntime/camera $(INC_rt_scene)
INC_rt_render  := -Iruntime/render $(INC_rt_camera)
INC_rt_aa      := -Iruntime/aa $(INC_rt_render)
INC_rt_effects := -Iruntime/effects $(INC_rt_aa)
INC_rt_truth   := -Iruntime/truth $(INC_rt_effects)
INC_rt_encode  := -Iruntime/encode $(INC_rt_truth)
INC_rt_write   := -Iruntime/write $(INC_rt_encode)
INC_rt_play    := -Iruntime/play $(INC_rt_write)
# seeing the runtime: seeing its top room, and so every room
INC_runtime  := $(INC_rt_play)
INC_roads    := -Iroads $(INC_base)
# libglscene (lib/, docs/api.md): the public API over the compiler and the
# runtime; include/ holds its one public header
INC_lib      := -Ilib -Iinclude $(INC_compiler) $(INC_runtime)
# glsroad's main also reads camera files and trajectories (runtime/camera)
INC_glsroad  := $(INC_roads) $(INC_rt_camera)
# An object sees the layer of its top directory (base/x.c: base), or in
# runtime/ the room of its folder (runtime/aa/x.c: aa).
LAYER_INC = $(if $(filter runtime,$(firstword $(subst /, ,$*))),$(INC_rt_$(word 2,$(subst /, ,$*))),$(INC_$(firstword $(subst /, ,$*))))
$(B)/roads/glsroad_main.o: LAYER_INC = $(INC_glsroad)
# The tools' mains that sit above the library (apps/): glsplay's sees the
# public header and the tools' helpers only: it goes through the library's
# API (docs/api.md "How glsplay uses it")
$(B)/apps/glsplay_main.o: LAYER_INC = -Iinclude $(INC_base)

# The GL backends (runtime/glctx_*.c, spec/backends.md): each is built when
# pkg-config finds its library, and left out otherwise or when GLS_NO_EGL=1
# or GLS_NO_OSMESA=1 says to build as if the library were absent
# (tests/e2e/build_backends.sh).  At least one is needed.  Every GL call
# goes through the backend (runtime/gl/glcalls.h), so no GL library is linked:
# only libEGL (libOSMesa is opened at run time, below).
HAVE_EGL    := $(if $(filter 1,$(GLS_NO_EGL)),,$(shell pkg-config --exists egl 2>/dev/null && echo 1))
HAVE_OSMESA := $(if $(filter 1,$(GLS_NO_OSMESA)),,$(shell pkg-config --exists osmesa 2>/dev/null && echo 1))
GLCTX_LEFT_OUT := $(if $(HAVE_EGL),,runtime/gl/glctx_egl.c) $(if $(HAVE_OSMESA),,runtime/gl/glctx_osmesa.c)
# libOSMesa is not linked but opened by its soname when the first OSMesa
# context is made (glctx_osmesa.c says why); the soname is the one the
# linker would have recorded, read from the library pkg-config finds.
OSMESA_SONAME := $(if $(HAVE_OSMESA),$(shell readelf -d "$$(pkg-config --variable=libdir osmesa)/libOSMesa.so" 2>/dev/null | sed -n 's/.*Library soname: \[\(.*\)\].*/\1/p'))
OSMESA_SONAME := $(or $(OSMESA_SONAME),libOSMesa.so.8)
GL_LIBS := $(if $(HAVE_EGL),$(shell pkg-config --libs egl)) $(if $(HAVE_OSMESA),-ldl) -lspng -pthread
$(B)/runtime/gl/glctx_egl.o: CFLAGS += $(shell pkg-config --cflags egl 2>/dev/null)
$(B)/runtime/gl/glctx_osmesa.o: CFLAGS += $(shell pkg-config --cflags osmesa 2>/dev/null)
# Which backends are in, for runtime/gl/glctx.c: written when the Makefile is
# read, and only when it changes, so that switching GLS_NO_EGL (or
# installing libegl-dev) recompiles glctx.c and relinks, and nothing else.
GLCTX_CONFIG := $(B)/gen/runtime/glctx_backends.h
GLCTX_CONFIG_TEXT := /* written by the Makefile: the GL backends of this build */\n\#define GLS_HAVE_EGL $(if $(HAVE_EGL),1,0)\n\#define GLS_HAVE_OSMESA $(if $(HAVE_OSMESA),1,0)\n
$(shell mkdir -p $(B)/gen/runtime && { printf '$(GLCTX_CONFIG_TEXT)' | cmp -s - $(GLCTX_CONFIG) || printf '$(GLCTX_CONFIG_TEXT)' >$(GLCTX_CONFIG); })
# the soname glctx_osmesa.c opens, in a header of its own (so that
# switching backends recompiles glctx.c alone)
OSMESA_CONFIG := $(B)/gen/runtime/glctx_osmesa_soname.h
OSMESA_CONFIG_TEXT := /* written by the Makefile: the library glctx_osmesa.c opens */\n\#define GLS_OSMESA_SONAME "$(OSMESA_SONAME)"\n
$(shell mkdir -p $(B)/gen/runtime && { printf '$(OSMESA_CONFIG_TEXT)' | cmp -s - $(OSMESA_CONFIG) || printf '$(OSMESA_CONFIG_TEXT)' >$(OSMESA_CONFIG); })

BASE_SRC     := $(wildcard base/*.c)
FORMAT_SRC   := $(wildcard format/*.c)
COMPILER_SRC := $(filter-out compiler/glsc_main.c compiler/glsdis_main.c,$(wildcard compiler/*.c))
RUNTIME_SRC  := $(filter-out $(GLCTX_LEFT_OUT),$(foreach r,$(RUNTIME_ROOMS),$(wildcard runtime/$(r)/*.c)))

BASE_OBJ     := $(BASE_SRC:%.c=$(B)/%.o)
FORMAT_OBJ   := $(FORMAT_SRC:%.c=$(B)/%.o)
COMPILER_OBJ := $(COMPILER_SRC:%.c=$(B)/%.o) $(B)/gen/lexer.o $(B)/gen/grammar.o
RUNTIME_OBJ  := $(RUNTIME_SRC:%.c=$(B)/%.o)
LIB_SRC      := $(wildcard lib/*.c)

# the libraries of each layer, in link order (a layer before those below it)
LIB_base     := $(B)/libglsbase.a
LIB_format   := $(B)/libglsformat.a $(LIB_base)
LIB_compiler := $(B)/libglscompiler.a $(LIB_format)
LIB_runtime  := $(B)/libglsruntime.a $(LIB_format)
LIB_roads    := $(B)/libglsroad.a $(LIB_base)
LIB_lib      := $(B)/libglscene.a

TOOLS := $(B)/glsc $(B)/glsdis $(B)/glsplay $(B)/glsroad
# libglscene, static and shared (below)
GLSCENE_LIBS := $(B)/libglscene.a $(B)/libglscene.so
# the scene library: textures, precompiled library bundle
SCENELIB := $(B)/textures.stamp $(B)/scenelib.glsb

UNIT_SRC := $(wildcard tests/unit/*.c)
UNIT_BIN := $(UNIT_SRC:tests/unit/%.c=$(B)/tests/%)
# The helper programs (benchmarks, image tools, fuzz seed writer): built by
# `make test` too, so that every program compiles and its dependencies are
# tracked like the rest.
PROGRAMS := $(B)/bench/play_floor $(B)/bench/play_bench $(B)/bench/aa_bench $(B)/bench/aa_exact $(B)/bench/instances_bench $(B)/bench/png_bench $(B)/depth2png $(B)/pnghalf \
            $(B)/road_montage $(B)/rawseed $(B)/distort_project $(B)/glsplay_bands_whole

.PHONY: gallery-truth gallery-effects gallery-road gl-backend-check all deps install uninstall test check demo demo-render demo-examples gallery clean bench-compile bench-play bench-instances fuzz-build bench-aa bench-backends bench-encode bench-scaling units programs spec-road-keys bench-distortion bench-effects bench-gpu
all: $(TOOLS) $(SCENELIB) $(GLSCENE_LIBS)
units: $(UNIT_BIN)
programs: $(PROGRAMS)

# No backend: say what to install (the #error in gl/glctx.c is the fallback).
$(B)/runtime/gl/glctx.o: $(GLCTX_CONFIG) | gl-backend-check
gl-backend-check:
	@[ -n "$(HAVE_EGL)$(HAVE_OSMESA)" ] || { echo "glscene: no GL backend to build: pkg-config finds neither egl (Debian: libegl-dev) nor osmesa (libosmesa6-dev)$(if $(filter 1,$(GLS_NO_EGL) $(GLS_NO_OSMESA)),; GLS_NO_EGL=1 / GLS_NO_OSMESA=1 left out what it finds)" >&2; exit 1; }

# The README's test command: install what is missing, build, run everything.
test:
	@sh tools/deps.sh
	@$(MAKE) --no-print-directory all units programs
	@GLS_BIN=$(B) sh tests/run.sh

# Programs (tools, unit tests, benchmarks, helpers): the main file is
# compiled like every object, with the include paths of what it sees, and
# linked with those layers' libraries.
.SECONDEXPANSION:

# Unit tests: each sees and links the layers it tests.
SEES_test_base := base
SEES_test_bundle := format
SEES_test_bundle_file := format
SEES_test_compile := compiler
SEES_test_lex := compiler
SEES_test_aa := bench
SEES_test_aa_lattice := bench
SEES_test_camera := runtime
SEES_test_player := runtime
SEES_test_plan_matrix := runtime
SEES_test_instances := runtime
SEES_test_pack := runtime
SEES_test_occlusion := runtime
SEES_test_outputs := runtime
SEES_test_writer := runtime
SEES_test_progress := runtime
SEES_test_progress_json := runtime
SEES_test_shard := runtime
SEES_test_rotation := runtime
SEES_test_subframe := runtime
SEES_test_gt_pass := runtime
SEES_test_gt_table := runtime
SEES_test_lighting := runtime
SEES_test_lens_truth := runtime
SEES_test_exact := bench
SEES_test_exact_edges := runtime
SEES_test_sensor := runtime
SEES_test_road_geo := roads
SEES_test_road_nurbs := roads
SEES_test_road_motion := roads runtime
SEES_test_road_traj := roads runtime
SEES_test_glscene := lib
# a program's include paths and libraries from the layers it sees
sees_inc = $(foreach l,$(1),$(INC_$(l)))
sees_lib = $(foreach l,$(1),$(LIB_$(l)))
$(UNIT_BIN): $(B)/tests/%: $(B)/tests/unit/%.o $$(call sees_lib,$$(SEES_$$*))
	$(CC) $(LDFLAGS) $(filter %.o,$^) -o $@ $(call sees_lib,$(SEES_$*)) $(LDLIBS) $(GL_LIBS)
# test_bundle_limit: the bundle reader with GLS_MAX_SECTION_RAW lowered (as
# the fuzz build lowers the unroll limits), so that sections can add up
# past it in a test.  Its own copy of format/bundle_read.c is linked
# before libglsformat.a, whose reader is then not pulled in.
SEES_test_bundle_limit := format
TEST_SECTION_RAW := -DGLS_MAX_SECTION_RAW='(1ull << 16)'
$(B)/tests/test_bundle_limit: $(B)/tests/limit/bundle_read.o
$(B)/tests/unit/test_bundle_limit.o: CFLAGS += $(TEST_SECTION_RAW)
$(B)/tests/limit/bundle_read.o: format/bundle_read.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(TEST_SECTION_RAW) $(INC_format) $(DEPFLAGS) -c $< -o $@
$(UNIT_BIN:$(B)/tests/%=$(B)/tests/unit/%.o): LAYER_INC = $(call sees_inc,$(SEES_$(notdir $*))) -Itests -Itests/unit

deps:
	@sh tools/deps.sh

$(B)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(LAYER_INC) $(DEPFLAGS) -c $< -o $@

# Generated sources: re2c lexer and lemon grammar, produced at build time.
$(B)/gen/lexer.c: compiler/lexer.re $(B)/gen/grammar.h
	@mkdir -p $(dir $@)
	re2c --no-generation-date --no-version -W -o $@ $<
# lemon leaves grammar.h alone when its content would not change: touch it,
# or it stays older than grammar.y and the grammar is made again on every
# run (and everything that includes grammar.h recompiled).  One rule makes
# both files, with grammar.c as its only target: a rule with two targets
# runs twice under -j (two copies raced on gen/grammar.y), and GNU make
# 4.3's grouped targets (&:) hide the recompile of grammar.c from make -n.
$(B)/gen/grammar.c: compiler/grammar.y
	@mkdir -p $(B)/gen
	cp compiler/grammar.y $(B)/gen/grammar.y
	cd $(B)/gen && lemon -q -T/usr/share/lemon/lempar.c grammar.y && touch grammar.h
$(B)/gen/grammar.h: $(B)/gen/grammar.c
	@test -f $@ || { rm -f $<; $(MAKE) --no-print-directory $<; }
$(B)/gen/%.o: $(B)/gen/%.c
	$(CC) $(CFLAGS) $(INC_compiler) -Wno-unused-parameter -Wno-unused-variable $(DEPFLAGS) -c $< -o $@
$(COMPILER_OBJ): | $(B)/gen/grammar.h

# Archives are written from scratch: `ar rcs` alone would keep the object
# of a deleted or moved source inside, and links would pick it up.  An
# archive (and the shared library) also depends on the list of its
# members, $(B)/members/NAME.list, which every make run rewrites while it
# reads this file (the end of it), but only when the list changed: so
# deleting, adding or moving a source rebuilds it, and `make -n` still
# shows only what would run (tests/e2e/build_archives.sh,
# readme_commands.sh).  Depending on the source directory's time instead
# missed a deletion made within the same tick of the kernel's coarse file
# clock as the archive (a few ms; seen on a fast machine).
ARCHIVE = rm -f $@ && $(AR) rcs $@ $(filter %.o,$^)
$(B)/members/%.list:
	@mkdir -p $(@D) && printf '%s\n' $(MEMBERS_$*) >$@
MEMBERS_base := $(BASE_OBJ)
MEMBERS_format := $(FORMAT_OBJ)
MEMBERS_compiler := $(COMPILER_OBJ)
MEMBERS_runtime := $(RUNTIME_OBJ)
$(B)/libglsbase.a: $(BASE_OBJ) $(B)/members/base.list
	$(ARCHIVE)
$(B)/libglsformat.a: $(FORMAT_OBJ) $(B)/members/format.list
	$(ARCHIVE)
$(B)/libglscompiler.a: $(COMPILER_OBJ) $(B)/members/compiler.list
	$(ARCHIVE)
$(B)/libglsruntime.a: $(RUNTIME_OBJ) $(B)/members/runtime.list
	$(ARCHIVE)

$(B)/glsc: $(B)/compiler/glsc_main.o $(LIB_compiler)
	$(CC) $(LDFLAGS) $^ -o $@ $(LDLIBS)
$(B)/glsdis: $(B)/compiler/glsdis_main.o $(LIB_compiler)
	$(CC) $(LDFLAGS) $^ -o $@ $(LDLIBS)
# glsplay is its main over libglscene.a's public API (glscene_play_*,
# lib/glscene_play*.c; tests/e2e/glsplay_public_api.sh); base for the
# tools' usage and standard output helpers, which the library leaves out.
$(B)/glsplay: $(B)/apps/glsplay_main.o $(B)/libglscene.a $(LIB_base)
	$(CC) $(LDFLAGS) $^ -o $@ $(LDLIBS) $(GL_LIBS)

# libglscene (docs/api.md): lib/ over every layer but roads, without the
# tools' helpers that print (base/usage.c, base/stdout_check.c): the
# library never writes to the standard streams.  The static library is
# the tools' objects; the shared one is a second set compiled with -fPIC
# under $(B)/pic/, so that the tools' code stays as it was.  The shared
# library exports glscene_* only (lib/glscene.map) and has the soname
# libglscene.so.MAJOR of include/glscene.h's GLSCENE_VERSION.
GLSCENE_VERSION := $(shell sed -n 's/^\#define GLSCENE_VERSION "\(.*\)"$$/\1/p' include/glscene.h)
GLSCENE_SONAME := libglscene.so.$(firstword $(subst ., ,$(GLSCENE_VERSION)))
# Every tool's --version prints it (base/usage.c, tests/e2e/version.sh),
# from a header written when the Makefile is read, and only when the
# version changed: so editing glscene.h otherwise recompiles only what
# includes it (tests/e2e/build_deps.sh), as glctx_backends.h above.
GLS_VERSION_H := $(B)/gen/base/gls_version.h
GLS_VERSION_TEXT := /* written by the Makefile: include/glscene.h'"'"'s GLSCENE_VERSION */\n\#define GLS_VERSION "$(GLSCENE_VERSION)"\n
$(shell mkdir -p $(B)/gen/base && { printf '$(GLS_VERSION_TEXT)' | cmp -s - $(GLS_VERSION_H) || printf '$(GLS_VERSION_TEXT)' >$(GLS_VERSION_H); })
$(B)/base/usage.o: LAYER_INC = $(INC_base) -I$(B)/gen/base
GLSCENE_OBJ := $(LIB_SRC:%.c=$(B)/%.o) $(filter-out $(B)/base/usage.o $(B)/base/stdout_check.o,$(BASE_OBJ)) \
               $(FORMAT_OBJ) $(COMPILER_OBJ) $(RUNTIME_OBJ)
GLSCENE_PIC_OBJ := $(GLSCENE_OBJ:$(B)/%=$(B)/pic/%)
MEMBERS_glscene := $(GLSCENE_OBJ)
MEMBERS_glscene_pic := $(GLSCENE_PIC_OBJ)
$(B)/libglscene.a: $(GLSCENE_OBJ) $(B)/members/glscene.list
	$(ARCHIVE)
# the undefined-symbol check, except under the sanitizers, whose runtime
# the program that loads the library brings
GLSCENE_NO_UNDEFINED := $(if $(filter 1,$(SANITIZE) $(FUZZ)),,-Wl,--no-undefined)
$(B)/libglscene.so.$(GLSCENE_VERSION): $(GLSCENE_PIC_OBJ) lib/glscene.map $(B)/members/glscene_pic.list
	$(CC) $(LDFLAGS) -shared -Wl,-soname,$(GLSCENE_SONAME) -Wl,--version-script=lib/glscene.map \
	    $(GLSCENE_NO_UNDEFINED) $(GLSCENE_PIC_OBJ) -o $@ $(LDLIBS) $(GL_LIBS)
$(B)/libglscene.so: $(B)/libglscene.so.$(GLSCENE_VERSION)
	ln -sf libglscene.so.$(GLSCENE_VERSION) $(B)/$(GLSCENE_SONAME)
	ln -sf $(GLSCENE_SONAME) $@
$(B)/pic/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -fPIC $(LAYER_INC) $(DEPFLAGS) -c $< -o $@
$(B)/pic/gen/%.o: $(B)/gen/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -fPIC $(INC_compiler) -Wno-unused-parameter -Wno-unused-variable $(DEPFLAGS) -c $< -o $@
$(GLSCENE_PIC_OBJ): | $(B)/gen/grammar.h
$(B)/pic/runtime/gl/glctx.o: $(GLCTX_CONFIG) | gl-backend-check
$(B)/pic/runtime/gl/glctx_egl.o: CFLAGS += $(shell pkg-config --cflags egl 2>/dev/null)
$(B)/pic/runtime/gl/glctx_osmesa.o: CFLAGS += $(shell pkg-config --cflags osmesa 2>/dev/null)
$(B)/pic/runtime/aa/aa.o: CFLAGS += -O3

# Fuzz targets (tests/fuzz/README.md): `make fuzz-build`, then
# `sh tests/fuzz/run.sh SECONDS` fuzzes every target.
FUZZ_TARGETS := compile bundle texture camera road writers
SEES_fuzz_compile := compiler
SEES_fuzz_texture := compiler
SEES_fuzz_bundle := runtime
SEES_fuzz_camera := runtime
SEES_fuzz_writers := runtime
SEES_fuzz_road := roads
$(B)/fuzz/fuzz_%: tests/fuzz/fuzz_%.c $$(call sees_lib,$$(SEES_fuzz_%))
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(call sees_inc,$(SEES_fuzz_$*)) -fsanitize=fuzzer $(DEPFLAGS) $< -o $@ \
	    $(call sees_lib,$(SEES_fuzz_$*)) $(LDLIBS) $(GL_LIBS)
fuzz-build:
	@$(MAKE) --no-print-directory B=build-fuzz CC=clang FUZZ=1 $(FUZZ_TARGETS:%=build-fuzz/fuzz/fuzz_%)
# rawseed: a bundle rewritten with uncompressed sections (fuzzing seeds)
$(B)/rawseed: $(B)/tests/fuzz/rawseed.o $(LIB_format)
	$(CC) $(LDFLAGS) $< -o $@ $(LIB_format) $(LDLIBS)
$(B)/tests/fuzz/rawseed.o: LAYER_INC = $(INC_format)

# Texture generator for the scene library and the examples (no binary
# textures are committed: they are made here, deterministically).
# The generator sees the base layer.
$(B)/gen_%.o: scenelib/gen/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(INC_base) $(DEPFLAGS) -c $< -o $@
$(B)/gen_textures: $(B)/gen_textures.o $(LIB_base)
	$(CC) $(LDFLAGS) $< -o $@ $(LIB_base) -lstb -lm
$(B)/textures.stamp: $(B)/gen_textures
	$(B)/gen_textures $(B)/textures && touch $@

# The scene library (scenelib/README.md) is the directory scenelib/, every
# object written in the scene language (its parameterised objects included);
# $(B)/scenelib.glsb is it precompiled with the textures, compiled from the
# repository root so that its source paths read scenelib/...:
# -I $(B)/scenelib.glsb stands for -I scenelib -I $(B)/textures.  It depends
# on the directories too, so that adding or removing an object rebuilds it.
SCENELIB_SRC := $(shell find scenelib -name '*.scene' 2>/dev/null)
SCENELIB_DIRS := $(shell find scenelib -type d 2>/dev/null)
$(B)/scenelib.glsb: $(B)/glsc $(B)/textures.stamp $(SCENELIB_SRC) $(SCENELIB_DIRS)
	$(B)/glsc -I $(B)/textures --lib scenelib -o $@

# distort_project: the lens model as a filter, for tests/py/check_distortion.py
$(B)/distort_project: $(B)/tools/distort_project.o $(LIB_runtime)
	$(CC) $(LDFLAGS) $< -o $@ $(LIB_runtime) $(LDLIBS) $(GL_LIBS)
$(B)/tools/distort_project.o: LAYER_INC = $(INC_runtime)
# glsplay_bands_whole: glsplay with each band of a rolling shutter drawn
# whole, for tests/e2e/rolling_bands.sh (a test's choice, set through the
# library's internal gls_api_play_opts, never read from the environment)
$(B)/glsplay_bands_whole: $(B)/tools/glsplay_bands_whole.o $(B)/libglscene.a
	$(CC) $(LDFLAGS) $^ -o $@ $(LDLIBS) $(GL_LIBS)
$(B)/tools/glsplay_bands_whole.o: LAYER_INC = $(INC_lib)

$(B)/depth2png: $(B)/tools/depth2png.o
	$(CC) $(LDFLAGS) $< -o $@ -lstb -lm

# The README's demo command: install what is missing, build, render the
# demo scene with a stereo pair of cameras into out/demo/ and the paper's
# figures (below).  Incremental: each render is a file target (a stamp
# under out/) that depends on its scene, cameras, bundle and tools, so a
# second `make demo` renders nothing, and touching a camera file renders
# again only the scene that camera belongs to (tests/e2e/readme_commands.sh).
demo:
	@sh tools/deps.sh
	@$(MAKE) --no-print-directory demo-render
demo-render: all out/demo/.stamp demo-examples
	@echo "demo: images, depth maps and point clouds are in out/demo/left and out/demo/right, the examples in out/<example>/"

DEMO_SRC := $(shell find examples/demo -name '*.scene' 2>/dev/null)
$(B)/demo.glsb: $(B)/glsc $(B)/textures.stamp $(DEMO_SRC)
	$(B)/glsc -I examples/demo -I $(B)/textures -o $@ examples/demo/Demo.scene
out/demo/.stamp: $(B)/demo.glsb $(B)/glsplay $(B)/depth2png examples/demo/left.cam examples/demo/right.cam examples/demo/left_sensor.cam
	$(B)/glsplay $(B)/demo.glsb --camera examples/demo/left.cam --camera examples/demo/right.cam --camera examples/demo/left_sensor.cam --aa 4 --background 0.55,0.7,0.9 -o out/demo
	$(B)/depth2png out/demo/left/depth_000000.pfm out/demo/left/depth_000000_view.png
	@touch $@

# The paper's figures (examples/*/README.md): calibration, stereo, dense
# stereo, grouping, lane, signs, rendered into out/<example>/, and their
# 320x240 gallery images into out/gallery/, one example per rule (its
# scene, its cameras, the scene library and the tools).
EXAMPLES := calibration stereo dense_stereo grouping lane signs lighting
define example_rule
out/$(1)/.stamp: $(wildcard examples/$(1)/*.scene examples/$(1)/*.cam) examples/render.sh $(B)/glsc $(B)/glsplay $(B)/depth2png $(B)/pnghalf $(B)/scenelib.glsb
	@mkdir -p out/gallery
	EXAMPLES_ONLY=$(1) sh examples/render.sh $(B) out out/gallery
	@touch $$@
endef
$(foreach e,$(EXAMPLES),$(eval $(call example_rule,$(e))))
demo-examples: $(EXAMPLES:%=out/%/.stamp)
$(B)/pnghalf: $(B)/tools/pnghalf.o
	$(CC) $(LDFLAGS) $< -o $@ -lstb -lm

# Regenerate the gallery images (docs/gallery.md) from the demo (committed copies).
gallery: demo $(B)/pnghalf
	cp out/demo/left/image_000000.png docs/demo_left.png
	cp out/demo/right/image_000000.png docs/demo_right.png
	cp out/demo/left/depth_000000_view.png docs/demo_left_depth.png
	cp out/demo/left_sensor/image_000000.png docs/demo_left_sensor.png
	cp out/gallery/ex_*.png docs/
	@$(MAKE) --no-print-directory gallery-effects

# The gallery's rows of camera effects (docs/gallery.md) (docs/effects_*.png): exposure, lens
# distortion and shadows on the demo's left camera.
gallery-effects: all $(B)/pnghalf
	sh bench/effects_o9/gallery.sh $(B) docs

# make install PREFIX=/usr/local DESTDIR=: the tools into PREFIX/bin, the
# standard library bundle (what `make` builds of scenelib/, textures
# included) into PREFIX/share/glscene/, a man page per tool
# (docs/man/*.1) into PREFIX/share/man/man1.  DESTDIR is prepended to
# every path (staged installs, packaging); nothing is written outside it.
# libglscene (docs/api.md): its header into PREFIX/include, the static and
# shared libraries (with the libglscene.so.0 and libglscene.so links) and
# glscene.pc into PREFIX/lib (pkgconfig/), the Python binding into
# PREFIX/lib/python3/dist-packages/glscene (where Debian's python3 looks
# for /usr/local and /usr; README "Use it from Python").
# make uninstall removes exactly those files (tests/e2e/install.sh).
PREFIX ?= /usr/local
DESTDIR ?=
INSTALL_BIN := $(DESTDIR)$(PREFIX)/bin
INSTALL_SHARE := $(DESTDIR)$(PREFIX)/share/glscene
INSTALL_MAN := $(DESTDIR)$(PREFIX)/share/man/man1
INSTALL_INC := $(DESTDIR)$(PREFIX)/include
INSTALL_LIB := $(DESTDIR)$(PREFIX)/lib
INSTALL_PY := $(INSTALL_LIB)/python3/dist-packages/glscene
GLSCENE_SO := libglscene.so.$(GLSCENE_VERSION)
MAN_PAGES := $(TOOLS:$(B)/%=docs/man/%.1)
install: $(TOOLS) $(SCENELIB) $(MAN_PAGES) $(GLSCENE_LIBS) lib/glscene.pc.in $(wildcard python/glscene/*.py)
	install -d $(INSTALL_BIN) $(INSTALL_SHARE) $(INSTALL_MAN) $(INSTALL_INC) $(INSTALL_LIB)/pkgconfig $(INSTALL_PY)
	install -m 755 $(TOOLS) $(INSTALL_BIN)/
	install -m 644 $(B)/scenelib.glsb $(INSTALL_SHARE)/scenelib.glsb
	install -m 644 $(MAN_PAGES) $(INSTALL_MAN)/
	install -m 644 include/glscene.h $(INSTALL_INC)/
	install -m 644 $(B)/libglscene.a $(INSTALL_LIB)/
	install -m 755 $(B)/$(GLSCENE_SO) $(INSTALL_LIB)/
	ln -sf $(GLSCENE_SO) $(INSTALL_LIB)/$(GLSCENE_SONAME)
	ln -sf $(GLSCENE_SONAME) $(INSTALL_LIB)/libglscene.so
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(GLSCENE_VERSION)|' \
	    -e 's|@LIBS_PRIVATE@|$(strip $(LDLIBS) $(GL_LIBS))|' lib/glscene.pc.in >$(INSTALL_LIB)/pkgconfig/glscene.pc
	install -m 644 $(wildcard python/glscene/*.py) $(INSTALL_PY)/
uninstall:
	rm -f $(TOOLS:$(B)/%=$(INSTALL_BIN)/%) $(INSTALL_SHARE)/scenelib.glsb $(MAN_PAGES:docs/man/%=$(INSTALL_MAN)/%)
	rm -f $(INSTALL_INC)/glscene.h $(INSTALL_LIB)/libglscene.a $(INSTALL_LIB)/$(GLSCENE_SO) \
	    $(INSTALL_LIB)/$(GLSCENE_SONAME) $(INSTALL_LIB)/libglscene.so $(INSTALL_LIB)/pkgconfig/glscene.pc
	rm -rf $(INSTALL_PY)
	-rmdir $(INSTALL_SHARE) 2>/dev/null

# Every bench-NAME writes its output (machine, load, tables) to
# $(B)/bench/NAME.txt and then into its block of docs/benchmarks.md, where
# the figures live beside the prose that reads them (tools/bench_md.sh).
BENCH_MD := sh tools/bench_md.sh --write
bench-compile: $(B)/glsc
	@mkdir -p $(B)/bench && sh bench/compile.sh $(B) >$(B)/bench/compile.txt; st=$$?; cat $(B)/bench/compile.txt; exit $$st
	@$(BENCH_MD) compile $(B)/bench/compile.txt

clean:
	rm -rf $(B) out

-include $(shell find $(B) -name '*.d' 2>/dev/null)

# The benchmarks see the runtime layer and the unit tests' scenes
# (tests/unit/player_scene.h); test_aa shares bench/aa_scene.h.
INC_bench := -Ibench -Itests/unit $(INC_runtime)
LIB_bench := $(LIB_runtime)
BENCH_BIN := $(B)/bench/play_floor $(B)/bench/play_bench $(B)/bench/aa_bench $(B)/bench/aa_exact $(B)/bench/instances_bench $(B)/bench/png_bench
$(BENCH_BIN): $(B)/bench/%: $(B)/bench/%.o $(LIB_bench)
	$(CC) $(LDFLAGS) $< -o $@ $(LIB_bench) $(LDLIBS) $(GL_LIBS)

# bench-play (runtime owner): player vs a minimal one-VBO floor, same
# context; issue 30's whole-process targets on its scattered scene.
bench-play: $(B)/bench/play_floor $(B)/bench/play_bench $(B)/glsplay
	@mkdir -p $(B)/bench && sh bench/play.sh $(B) >$(B)/bench/play.txt; st=$$?; cat $(B)/bench/play.txt; exit $$st
	@$(BENCH_MD) play $(B)/bench/play.txt

# bench-instances (runtime owner): instanced replay against --flatten and
# the floor, random-order triangles and a 10,000-tree forest
# (docs/benchmarks.md; minutes: the flattened forest has 20 M triangles).
bench-instances: $(B)/bench/play_floor $(B)/bench/instances_bench
	@sh bench/instances.sh $(B)
	@$(BENCH_MD) instances $(B)/bench/instances.txt

# bench-encode: what writing the files costs glsplay: frames per second
# with and without image files, writer thread on and off, 640x480 and
# 1920x1080, and each PNG encoder and level on one frame; writes
# docs/benchmarks.md (BE_BASELINE=path/to/old/glsplay adds a column).
bench-encode: $(TOOLS) $(SCENELIB) $(B)/bench/play_bench $(B)/bench/png_bench
	@sh bench/encode.sh $(B)
	@$(BENCH_MD) encode $(B)/bench/encode.txt

# bench-backends: frames per second of each GL backend (spec/backends.md),
# the road sequence and the 100k-triangle terrain, 1 and 256 samples a
# pixel; writes docs/benchmarks.md.
bench-backends: $(TOOLS) $(SCENELIB) $(B)/bench/play_bench
	@sh bench/backends.sh $(B)
	@$(BENCH_MD) backends $(B)/bench/backends.txt

# bench-scaling: frames per second with 1 and 2 processes (--shard) and
# LP_NUM_THREADS 1, 2 and unset, the road sequence and the 100k-triangle
# terrain; writes docs/benchmarks.md (docs/cluster.md points there).
bench-scaling: $(TOOLS) $(SCENELIB) $(B)/bench/play_bench
	@sh bench/scaling.sh $(B)
	@$(BENCH_MD) scaling $(B)/bench/scaling.txt
# bench-distortion: lens distortion's time per frame (road demo), edge
# accuracy and the 15-view calibration (docs/benchmarks.md; DB_BASELINE=
# a glsplay from before the lens adds its pinhole time).
bench-distortion: $(TOOLS) $(SCENELIB)
	@sh bench/distortion.sh $(B)
	@$(BENCH_MD) distortion $(B)/bench/distortion.txt
# bench-effects: the effects' cost, and none when unused, against the build
# before issue 16 (bench/effects.sh, docs/benchmarks.md).
bench-effects: $(TOOLS) $(SCENELIB) $(B)/bench/play_bench
	@sh bench/effects.sh $(B)
	@$(BENCH_MD) effects $(B)/bench/effects.txt

# bench-gpu: frames/s of whole glsplay runs on the road demo, a 10,000-tree
# forest and 100,000 scattered triangles at 640x480 and 1920x1080 through EGL
# (a GPU where there is one), and the bench-play and bench-instances
# programs (bench/gpu.sh).  Without a GPU it measures llvmpipe, slowly
# (GPU_FRAMES frames a run, default 120).
bench-gpu: $(TOOLS) $(SCENELIB) $(B)/bench/play_floor $(B)/bench/play_bench $(B)/bench/instances_bench
	@sh bench/gpu.sh prepare $(B) $(B)/bench/gpu-inputs
	@sh bench/gpu.sh run $(B) $(B)/bench/gpu-inputs egl $(or $(GPU_FRAMES),120) >$(B)/bench/gpu.txt; st=$$?; cat $(B)/bench/gpu.txt; exit $$st
	@$(BENCH_MD) gpu $(B)/bench/gpu.txt

# bench-aa (runtime owner): cost and edge accuracy of anti-aliasing.
# the plot needs gnuplot (gnuplot-nox), which bench/aa.sh installs if missing.
bench-aa: $(B)/bench/aa_bench $(B)/bench/aa_exact $(TOOLS) $(SCENELIB)
	@sh bench/aa.sh $(B)
	@$(BENCH_MD) aa $(B)/bench/aa.txt
# The accumulator's add loops are the per-sample CPU cost of anti-aliasing;
# -O3 vectorises them (gcc 12's -O2 leaves loops with remainders scalar).
$(B)/runtime/aa/aa.o: CFLAGS += -O3
$(B)/runtime/aa/exact_image.o $(B)/runtime/aa/exact_scene.o: CFLAGS += -O3

# glsroad (roads/, spec/road.md): road descriptions -> scene, trajectory,
# ground truth.  Library libglsroad.a (tests link it) and the tool.
ROAD_SRC := $(filter-out roads/glsroad_main.c,$(wildcard roads/*.c))
ROAD_OBJ := $(ROAD_SRC:%.c=$(B)/%.o)
MEMBERS_roads := $(ROAD_OBJ)
$(B)/libglsroad.a: $(ROAD_OBJ) $(B)/members/roads.list
	$(ARCHIVE)
$(B)/glsroad: $(B)/roads/glsroad_main.o $(LIB_roads) $(LIB_runtime)
	$(CC) $(LDFLAGS) $< $(LIB_roads) $(LIB_runtime) -o $@ $(LDLIBS)
# spec/road.md's tables of keys, written from the parser's table
# (roads/road_keys.c) by glsroad --list-keys; tests/e2e/road_keys.sh checks
# that the spec holds them.
spec-road-keys: $(B)/glsroad
	sh tools/spec_road_keys.sh --write $(B)/glsroad spec/road.md
$(B)/road_montage: $(B)/examples/road/montage.o
	$(CC) $(LDFLAGS) $< -o $@ -lstb -lm

# demo-road: the example road (examples/road/demo.road) rendered as a short
# stereo sequence into out/road/, and a strip of frames,
# out/road/road_strip.png.  examples/road/render.sh: glsroad, glsc, then
# one glsplay --trajectory --motion over the selected frames (where glsplay
# lacks --motion, a scene per frame; see examples/road/README.md).  Like
# every command the README gives a user, it writes only under out/ and
# $(B)/; the targets that rewrite committed files (gallery, gallery-*,
# bench-*, spec-road-keys) are the maintainer's (tests/e2e/readme_commands.sh
# checks that make -n demo and demo-road name no docs/ path).
demo-road:
	@sh tools/deps.sh
	@$(MAKE) --no-print-directory all $(B)/textures.stamp $(B)/road_montage
	sh examples/road/render.sh $(B) out/road out/road/road_strip.png
# docs/roads.md's strip, docs/road_strip.png, from demo-road's.
gallery-road: demo-road
	cp out/road/road_strip.png docs/road_strip.png

# The README's ground-truth row (and docs/gallery.md's) (docs/gt_*.png): colour views of
# the road clip's answer-key files (frame 200) and the stereo example's
# disparity, made by tools/gt_gallery.py (cv2, numpy).
gallery-truth: demo-road out/stereo/.stamp
	/usr/bin/python3 tools/gt_gallery.py out/road/clip 200 out/stereo docs

# The archives' member lists (see ARCHIVE above), brought up to date while
# make reads this file, after every MEMBERS_ list is defined.
MEMBER_LISTS := base format compiler runtime glscene glscene_pic roads
# (each run writes its own temporary, .new.PID, so that runs at once agree)
members_sync = mkdir -p $(B)/members && $(foreach m,$(MEMBER_LISTS),printf '%s\n' $(MEMBERS_$(m)) >$(B)/members/$(m).list.new.$$$$ && \
    { cmp -s $(B)/members/$(m).list.new.$$$$ $(B)/members/$(m).list && rm -f $(B)/members/$(m).list.new.$$$$ || \
      mv -f $(B)/members/$(m).list.new.$$$$ $(B)/members/$(m).list; } &&) true
$(if $(filter clean,$(MAKECMDGOALS)),,$(shell $(members_sync)))
