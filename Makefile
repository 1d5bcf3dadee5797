# Thin wrappers around CMake. `make demo` and `make test` work on a fresh Debian machine.
BUILD ?= build
JOBS ?= $(shell nproc)
SHARED ?= $(abspath ../shared)
DEMO_SPP ?= 64
# The sanitizer build (ASan + UBSan with clang, cmake/sanitize.cmake), which also builds the fuzzer.
SAN_BUILD ?= build-sanitize

.PHONY: setup configure build demo test test-long python sanitize-configure sanitize-build test-sanitize bench \
	fuzz format clean

setup:
	bash scripts/setup.sh

configure: setup
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DILLUM_SHARED_DIR=$(SHARED)

build: configure
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	./$(BUILD)/illum render --spp $(DEMO_SPP) -o cornell-box.png -o cornell-box.exr

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) -LE long

# The Python module (python/) into $(BUILD)/python: PYTHONPATH=$(BUILD)/python python3 -c "import illum".
python: configure
	cmake --build $(BUILD) -j $(JOBS) --target illum_python

# tests/long/ (label long); fails when no test matched.
test-long: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) -L long --no-tests=error

sanitize-configure: setup
	cmake -C cmake/sanitize.cmake -S . -B $(SAN_BUILD) -DILLUM_SHARED_DIR=$(SHARED)

sanitize-build: sanitize-configure
	cmake --build $(SAN_BUILD) -j $(JOBS)

# Every test but the long ones under AddressSanitizer + UndefinedBehaviorSanitizer, and a 60 s fuzz run
# (label sanitize); any sanitizer report fails its test.
test-sanitize: sanitize-build
	ctest --test-dir $(SAN_BUILD) --output-on-failure -j $(JOBS) -LE long --no-tests=error

FUZZ_SECONDS ?= 60

# libFuzzer run of the parser, the scene builder and a tiny render (fuzz/pbrt_scene_fuzz.cpp), built by the
# sanitizer build; the corpus grows in $(SAN_BUILD)/fuzz-long.
fuzz: sanitize-configure
	cmake --build $(SAN_BUILD) -j $(JOBS) --target pbrt_scene_fuzz
	bash fuzz/run.sh $(SAN_BUILD)/fuzz-target/pbrt_scene_fuzz $(SAN_BUILD)/fuzz-long $(FUZZ_SECONDS) $(SHARED)

bench: build
	./$(BUILD)/illum bench
	./$(BUILD)/illum_bench

format:
	clang-format -i $$(git ls-files '*.h' '*.cpp')

clean:
	rm -rf $(BUILD) $(SAN_BUILD)
