# glscene build.  `make` builds the tools into build/; `make test` runs the
# test suite; `make demo` renders the demo.  Both install missing Debian
# packages first (tools/deps.sh).
CC      ?= cc
CSTD    := -std=c11 -D_XOPEN_SOURCE=700
WARN    := -Wall -Wextra -Werror
OPT     ?= -O2 -g
CFLAGS  += $(CSTD) $(WARN) $(OPT) -Iformat -Icompiler -Iruntime -I$(B)/gen
LDLIBS  := -lzstd -lz -lstb -lm

ifeq ($(SANITIZE),1)
CFLAGS  += -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
LDFLAGS += -fsanitize=address,undefined
endif

B ?= build

FORMAT_SRC   := $(wildcard format/*.c)
COMPILER_SRC := $(filter-out compiler/glsc_main.c compiler/glsdis_main.c,$(wildcard compiler/*.c))
RUNTIME_SRC  := $(filter-out runtime/glsplay_main.c,$(wildcard runtime/*.c))

FORMAT_OBJ   := $(FORMAT_SRC:%.c=$(B)/%.o)
COMPILER_OBJ := $(COMPILER_SRC:%.c=$(B)/%.o) $(B)/gen/lexer.o $(B)/gen/grammar.o
RUNTIME_OBJ  := $(RUNTIME_SRC:%.c=$(B)/%.o)

TOOLS := $(B)/glsc $(B)/glsdis $(B)/glsplay

GL_LIBS := -lOSMesa -lGL -lspng

UNIT_SRC := $(wildcard tests/unit/*.c)
UNIT_BIN := $(UNIT_SRC:tests/unit/%.c=$(B)/tests/%)

.PHONY: all deps test check demo clean bench-compile bench-play
all: $(TOOLS)

# The README's test command: install what is missing, build, run everything.
test:
	@sh tools/deps.sh
	@$(MAKE) --no-print-directory all $(UNIT_BIN)
	@GLS_BIN=$(B) sh tests/run.sh

$(B)/tests/%: tests/unit/%.c $(B)/libglscompiler.a $(B)/libglsruntime.a $(B)/libglsformat.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -Itests $(LDFLAGS) $< -o $@ $(B)/libglscompiler.a $(B)/libglsruntime.a $(B)/libglsformat.a $(LDLIBS) $(GL_LIBS)

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
	$(CC) $(CFLAGS) -Wno-unused-parameter -Wno-unused-variable -Icompiler -c $< -o $@
$(COMPILER_OBJ): | $(B)/gen/grammar.h

$(B)/libglsformat.a: $(FORMAT_OBJ)
	$(AR) rcs $@ $^
$(B)/libglscompiler.a: $(COMPILER_OBJ)
	$(AR) rcs $@ $^
$(B)/libglsruntime.a: $(RUNTIME_OBJ)
	$(AR) rcs $@ $^

$(B)/glsc: $(B)/compiler/glsc_main.o $(B)/libglscompiler.a $(B)/libglsformat.a
	$(CC) $(LDFLAGS) $^ -o $@ $(LDLIBS)
$(B)/glsdis: $(B)/compiler/glsdis_main.o $(B)/libglscompiler.a $(B)/libglsformat.a
	$(CC) $(LDFLAGS) $^ -o $@ $(LDLIBS)
$(B)/glsplay: $(B)/runtime/glsplay_main.o $(B)/libglsruntime.a $(B)/libglsformat.a
	$(CC) $(LDFLAGS) $^ -o $@ $(LDLIBS) $(GL_LIBS)

# Texture generator for the scene library and the examples (no binary
# textures are committed: they are made here, deterministically).
$(B)/gen_textures: scenelib/gen/textures.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $< -o $@ -lstb -lm
$(B)/textures.stamp: $(B)/gen_textures
	$(B)/gen_textures $(B)/textures && touch $@

# The README's demo command: install what is missing, build, render the
# demo scene with a stereo pair of cameras into out/demo/.
demo:
	@sh tools/deps.sh
	@$(MAKE) --no-print-directory all $(B)/textures.stamp
	$(B)/glsc -I examples/demo -I $(B)/textures -o $(B)/demo.glsb examples/demo/Demo.scene
	$(B)/glsplay $(B)/demo.glsb --camera examples/demo/left.cam --camera examples/demo/right.cam -o out/demo
	@echo "demo: images, depth maps and point clouds are in out/demo/left and out/demo/right"

bench-compile: $(B)/glsc
	@sh bench/compile.sh $(B)

clean:
	rm -rf $(B) out

-include $(shell find $(B) -name '*.d' 2>/dev/null)

# bench-play (runtime owner): player vs a minimal one-VBO floor, same context.
$(B)/bench/play_floor: bench/play_floor.c bench/play_scene.h $(B)/libglsruntime.a $(B)/libglsformat.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -Ibench $(LDFLAGS) $< -o $@ $(B)/libglsruntime.a $(B)/libglsformat.a $(LDLIBS) $(GL_LIBS)
$(B)/bench/play_bench: bench/play_bench.c bench/play_scene.h tests/unit/player_scene.h $(B)/libglsruntime.a $(B)/libglsformat.a
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -Ibench $(LDFLAGS) $< -o $@ $(B)/libglsruntime.a $(B)/libglsformat.a $(LDLIBS) $(GL_LIBS)
bench-play: $(B)/bench/play_floor $(B)/bench/play_bench
	@sh bench/play.sh $(B)
