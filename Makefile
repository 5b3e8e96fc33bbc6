# glintlab: the two set-up commands are `make demo` and `make test`.
# Every target installs missing Debian packages first (scripts/install-deps.sh).

JOBS        ?= $(shell nproc)
BUILD       ?= build/release
BUILD_ASAN  ?= build/asan
BUILD_FUZZ  ?= build/fuzz
CMAKE_FLAGS ?=

.PHONY: all deps configure build demo test test-asan fuzz-build fuzz-ci fuzz-long bench web clean

all: build

deps:
	@bash scripts/install-deps.sh

$(BUILD)/build.ninja: | deps
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: deps $(BUILD)/build.ninja
	cmake --build $(BUILD) -j $(JOBS)

# Renders the default scene to out/default.exr and out/default.png.
demo: build
	@mkdir -p out
	$(BUILD)/glintlab render scenes/default.json -o out/default.exr

# Builds Release and runs the whole test suite through ctest.
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# -O1 -g1 (line tables): the sanitizers' reports keep file:line while the
# tree compiles in about half the time of -O2 -g (measured per translation
# unit: 27.6 s -> 12.6 s of CPU for compare.cpp), the larger part of CI.
ASAN_OPT_FLAGS = -O1 -g1 -DNDEBUG
$(BUILD_ASAN)/build.ninja: | deps
	cmake -S . -B $(BUILD_ASAN) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGLINTLAB_SANITIZE=ON \
	    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(ASAN_OPT_FLAGS)" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$(ASAN_OPT_FLAGS)" \
	    $(CMAKE_FLAGS)

# The same suite under AddressSanitizer + UndefinedBehaviorSanitizer.
# intercept_tls_get_addr=0: GCC 12's LeakSanitizer, tracking the dynamic TLS
# of Mesa's dlopen'd driver threads, reads a stale block range at exit and
# its tracer crashes (SIGSEGV in "Processing thread ... DTLS", after the test
# passed; depends on the memory layout). Our code has no dynamic TLS, so
# this only drops that driver's TLS from the leak roots.
test-asan: deps $(BUILD_ASAN)/build.ninja
	cmake --build $(BUILD_ASAN) -j $(JOBS) --target glintlab_tests glintlab_cli
	cd $(BUILD_ASAN) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:intercept_tls_get_addr=0 \
	    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	    GLINTLAB_SANITIZED=1 ctest --output-on-failure -j $(JOBS)

# libFuzzer targets (docs/VALIDATION.md, "Fuzzing"): a lean clang tree with
# only the loaders, under AddressSanitizer + UndefinedBehaviorSanitizer.
$(BUILD_FUZZ)/build.ninja: | deps
	cmake -S . -B $(BUILD_FUZZ) -G Ninja -DGLINTLAB_FUZZ=ON \
	    -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang $(CMAKE_FLAGS)

fuzz-build: deps $(BUILD_FUZZ)/build.ninja
	cmake --build $(BUILD_FUZZ) -j $(JOBS)

# CI: each target 60 s (FUZZ_SECONDS), two at a time, from the seeds and the
# regression inputs; about 4-5 minutes with the build on 2 cores.
fuzz-ci: fuzz-build
	BUILD_FUZZ=$(BUILD_FUZZ) scripts/fuzz.sh ci

# Long runs: each target FUZZ_SECONDS (default 3600) with FUZZ_JOBS workers
# (default: all cores), the corpus kept in $(BUILD_FUZZ)/corpus between runs.
fuzz-long: fuzz-build
	BUILD_FUZZ=$(BUILD_FUZZ) scripts/fuzz.sh long

bench: build
	$(BUILD)/glintlab_bench

# The WebGL2 page (docs/WEB.md): exports every model's GLSL ES shader and
# resources into web/export/; then `python3 -m http.server` in the
# repository root and http://localhost:8000/web/.
web: build
	bash scripts/export_web.sh $(BUILD)/glintlab web/export

clean:
	rm -rf build out
