# glscene build.  `make` builds the tools into build/; `make test` runs the
# test suite; `make demo` renders the demo.  Both install missing Debian
# packages first (tools/deps.sh).
CC      ?= cc
CSTD    := -std=c11 -D_XOPEN_SOURCE=700
WARN    := -Wall -Wextra -Werror
OPT     ?= -O2 -g
CFLAGS  += $(CSTD) $(WARN) $(OPT) -Ibase -Iformat -Icompiler -Iruntime -I$(B)/gen
LDLIBS  := -lzstd -lz -lstb -lm

ifeq ($(SANITIZE),1)
CFLAGS  += -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
LDFLAGS += -fsanitize=address,undefined
endif

B ?= build

# FUZZ=1: libFuzzer coverage instrumentation plus ASan and UBSan (clang).
ifeq ($(FUZZ),1)
CFLAGS  += -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
LDFLAGS += -fsanitize=address,undefined
endif

BASE_SRC     := $(wildcard base/*.c)
FORMAT_SRC   := $(wildcard format/*.c)
COMPILER_SRC := $(filter-out compiler/glsc_main.c compiler/glsdis_main.c,$(wildcard compiler/*.c))
RUNTIME_SRC  := $(filter-out runtime/glsplay_main.c,$(wildcard runtime/*.c))

BASE_OBJ     := $(BASE_SRC:%.c=$(B)/%.o)
FORMAT_OBJ   := $(FORMAT_SRC:%.c=$(B)/%.o)
COMPILER_OBJ := $(COMPILER_SRC:%.c=$(B)/%.o) $(B)/gen/lexer.o $(B)/gen/grammar.o
RUNTIME_OBJ  := $(RUNTIME_SRC:%.c=$(B)/%.o)

TOOLS := $(B)/glsc $(B)/glsdis $(B)/glsplay $(B)/glsroad
# the scene library: textures, object generator, precompiled library bundle
SCENELIB := $(B)/textures.stamp $(B)/gen_objects $(B)/scenelib.glsb

GL_LIBS := -lOSMesa -lGL -lspng

UNIT_SRC := $(wildcard tests/unit/*.c)
UNIT_BIN := $(UNIT_SRC:tests/unit/%.c=$(B)/tests/%)

.PHONY: all deps test check demo demo-examples gallery clean bench-compile bench-play fuzz-build bench-aa
all: $(TOOLS) $(SCENELIB)

# The README's test command: install what is missing, build, run everything.
test:
	@sh tools/deps.sh
	@$(MAKE) --no-print-directory all $(UNIT_BIN)
	@GLS_BIN=$(B) sh tests/run.sh

$(B)/tests/%: tests/unit/%.c $(B)/libglscompiler.a $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -Itests $(LDFLAGS) $< -o $@ $(B)/libglscompiler.a $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a $(LDLIBS) $(GL_LIBS)

deps:
	@sh tools/deps.sh

$(B)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -MMD -MP -c $< -o $@

# Generated sources: re2c lexer and lemon grammar, produced at build time.
$(B)/gen/lexer.c: compiler/lexer.re $(B)/gen/grammar.h
	@mkdir -p $(dir $@)
	re2c --no-generation-date --no-version -W -o $@ $<
$(B)/gen/grammar.c $(B)/gen/grammar.h: compiler/grammar.y
	@mkdir -p $(B)/gen
	cp compiler/grammar.y $(B)/gen/grammar.y
	cd $(B)/gen && lemon -q -T/usr/share/lemon/lempar.c grammar.y
$(B)/gen/%.o: $(B)/gen/%.c
	$(CC) $(CFLAGS) -Wno-unused-parameter -Wno-unused-variable -Icompiler -MMD -MP -c $< -o $@
$(COMPILER_OBJ): | $(B)/gen/grammar.h

$(B)/libglsbase.a: $(BASE_OBJ)
	$(AR) rcs $@ $^
$(B)/libglsformat.a: $(FORMAT_OBJ)
	$(AR) rcs $@ $^
$(B)/libglscompiler.a: $(COMPILER_OBJ)
	$(AR) rcs $@ $^
$(B)/libglsruntime.a: $(RUNTIME_OBJ)
	$(AR) rcs $@ $^

$(B)/glsc: $(B)/compiler/glsc_main.o $(B)/libglscompiler.a $(B)/libglsformat.a $(B)/libglsbase.a
	$(CC) $(LDFLAGS) $^ -o $@ $(LDLIBS)
$(B)/glsdis: $(B)/compiler/glsdis_main.o $(B)/libglscompiler.a $(B)/libglsformat.a $(B)/libglsbase.a
	$(CC) $(LDFLAGS) $^ -o $@ $(LDLIBS)
$(B)/glsplay: $(B)/runtime/glsplay_main.o $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a
	$(CC) $(LDFLAGS) $^ -o $@ $(LDLIBS) $(GL_LIBS)

# Fuzz targets (tests/fuzz/README.md): `make fuzz-build`, then
# `sh tests/fuzz/run.sh SECONDS` fuzzes every target.
FUZZ_TARGETS := compile bundle texture camera road writers
$(B)/fuzz/fuzz_%: tests/fuzz/fuzz_%.c $(B)/libglscompiler.a $(B)/libglsruntime.a $(B)/libglsroad.a $(B)/libglsformat.a $(B)/libglsbase.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -Iroads -fsanitize=fuzzer $< -o $@ $(B)/libglscompiler.a $(B)/libglsroad.a $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a $(LDLIBS) $(GL_LIBS)
fuzz-build:
	@$(MAKE) --no-print-directory B=build-fuzz CC=clang FUZZ=1 $(FUZZ_TARGETS:%=build-fuzz/fuzz/fuzz_%)

# Texture generator for the scene library and the examples (no binary
# textures are committed: they are made here, deterministically).
$(B)/gen_textures: scenelib/gen/textures.c $(B)/libglsbase.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $^ -o $@ -lstb -lm
$(B)/textures.stamp: $(B)/gen_textures
	$(B)/gen_textures $(B)/textures && touch $@

# The scene library (scenelib/README.md).  Its parametric objects are
# written by scenelib/gen/objects.c and committed; `make gen-scenelib`
# rewrites them (removing generated files first, so none go stale) and
# tests/e2e/scenelib.sh checks they are up to date.  $(B)/scenelib.glsb is
# the whole library precompiled: -I $(B)/scenelib.glsb stands for
# -I scenelib -I $(B)/textures.
SCENELIB_SRC := $(shell find scenelib -name '*.scene' 2>/dev/null)
$(B)/gen_objects: scenelib/gen/objects.c $(B)/libglsbase.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $^ -o $@ -lm
$(B)/scenelib.glsb: $(B)/glsc $(B)/textures.stamp $(SCENELIB_SRC)
	$(B)/glsc -I $(B)/textures --lib scenelib -o $@
.PHONY: gen-scenelib
gen-scenelib: $(B)/gen_objects
	grep -rl --include='*.scene' '^// Generated by scenelib/gen/objects.c' scenelib | xargs rm -f
	$(B)/gen_objects scenelib >/dev/null

$(B)/depth2png: tools/depth2png.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $< -o $@ -lstb -lm

# The README's demo command: install what is missing, build, render the
# demo scene with a stereo pair of cameras into out/demo/.
demo:
	@sh tools/deps.sh
	@$(MAKE) --no-print-directory all $(B)/textures.stamp $(B)/depth2png $(B)/pnghalf
	$(B)/glsc -I examples/demo -I $(B)/textures -o $(B)/demo.glsb examples/demo/Demo.scene
	$(B)/glsplay $(B)/demo.glsb --camera examples/demo/left.cam --camera examples/demo/right.cam --aa 4 --background 0.55,0.7,0.9 -o out/demo
	$(B)/depth2png out/demo/left/depth_000000.pfm out/demo/left/depth_000000_view.png
	@echo "demo: images, depth maps and point clouds are in out/demo/left and out/demo/right"
	@$(MAKE) --no-print-directory demo-examples

# The paper's figures (examples/*/README.md): calibration, stereo, dense
# stereo, grouping, lane, signs, rendered into out/<example>/, and their
# 320x240 gallery images into out/gallery/.
demo-examples: all $(B)/depth2png $(B)/pnghalf
	@mkdir -p out/gallery
	sh examples/render.sh $(B) out out/gallery
$(B)/pnghalf: tools/pnghalf.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $< -o $@ -lstb -lm

# Regenerate the README's gallery images from the demo (committed copies).
gallery: demo
	cp out/demo/left/image_000000.png docs/demo_left.png
	cp out/demo/right/image_000000.png docs/demo_right.png
	cp out/demo/left/depth_000000_view.png docs/demo_left_depth.png
	cp out/gallery/ex_*.png docs/

bench-compile: $(B)/glsc
	@sh bench/compile.sh $(B)

clean:
	rm -rf $(B) out

-include $(shell find $(B) -name '*.d' 2>/dev/null)

# bench-play (runtime owner): player vs a minimal one-VBO floor, same context.
$(B)/bench/play_floor: bench/play_floor.c bench/play_scene.h $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -Ibench $(LDFLAGS) $< -o $@ $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a $(LDLIBS) $(GL_LIBS)
$(B)/bench/play_bench: bench/play_bench.c bench/play_scene.h tests/unit/player_scene.h $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -Ibench $(LDFLAGS) $< -o $@ $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a $(LDLIBS) $(GL_LIBS)
bench-play: $(B)/bench/play_floor $(B)/bench/play_bench
	@sh bench/play.sh $(B)

# bench-aa (runtime owner): cost and edge accuracy of anti-aliasing.
$(B)/bench/aa_bench: bench/aa_bench.c bench/aa_scene.h tests/unit/player_scene.h $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -Ibench $(LDFLAGS) $< -o $@ $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a $(LDLIBS) $(GL_LIBS)
bench-aa: $(B)/bench/aa_bench $(TOOLS) $(SCENELIB)
	@sh bench/aa.sh $(B)
# The accumulator's add loops are the per-sample CPU cost of anti-aliasing;
# -O3 vectorises them (gcc 12's -O2 leaves loops with remainders scalar).
$(B)/runtime/aa.o: CFLAGS += -O3

# glsroad (roads/, spec/road.md): road descriptions -> scene, trajectory,
# ground truth.  Library libglsroad.a (tests link it) and the tool.
ROAD_SRC := $(filter-out roads/glsroad_main.c,$(wildcard roads/*.c))
ROAD_OBJ := $(ROAD_SRC:%.c=$(B)/%.o)
$(B)/libglsroad.a: $(ROAD_OBJ)
	$(AR) rcs $@ $^
$(B)/glsroad: $(B)/roads/glsroad_main.o $(B)/libglsroad.a $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a
	$(CC) $(LDFLAGS) $^ -o $@ $(LDLIBS)
$(B)/tests/test_road%: tests/unit/test_road%.c $(B)/libglsroad.a $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -Itests -Iroads -Ibase $(LDFLAGS) $< -o $@ $(B)/libglsroad.a $(B)/libglsruntime.a $(B)/libglsformat.a $(B)/libglsbase.a $(LDLIBS)
$(B)/road_montage: examples/road/montage.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $< -o $@ -lstb -lm

# demo-road: the example road (examples/road/demo.road) rendered as a short
# stereo sequence into out/road/, and a strip of frames, docs/road_strip.png.
# examples/road/render.sh renders each selected frame with glsplay
# --trajectory --frames F:F+1, after compiling that frame's placement of the
# moving vehicles.
demo-road:
	@sh tools/deps.sh
	@$(MAKE) --no-print-directory all $(B)/textures.stamp $(B)/road_montage
	sh examples/road/render.sh $(B) out/road docs/road_strip.png
