# Thin wrappers around CMake. `make demo` and `make test` work on a fresh Debian machine.
BUILD ?= build
JOBS ?= $(shell nproc)
SHARED ?= $(abspath ../shared)
DEMO_SPP ?= 64

.PHONY: setup configure build demo test test-long bench fuzz format clean

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

test-long: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) -L long

FUZZ_SECONDS ?= 60

# libFuzzer run of the pbrt tokenizer/parser and PLY reader (needs clang; `make setup` installs it).
fuzz:
	bash fuzz/run.sh $(BUILD)-fuzz $(FUZZ_SECONDS) $(SHARED)

bench: build
	./$(BUILD)/illum bench
	./$(BUILD)/illum_bench

format:
	clang-format -i $$(git ls-files '*.h' '*.cpp')

clean:
	rm -rf $(BUILD)
