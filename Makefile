# Thin wrapper: the two set-up commands of the README.
#   make demo  - install missing Debian packages, build, verify a bundled example
#   make test  - install missing Debian packages, build, run the whole test
#                suite, then the sanitizer stage (make sanitize)
#   make sanitize - the unit, crosscheck, property (fewer cases) and CLI
#                suites again (the CLI suite without the bundled
#                examples' certificate round trips: minutes under ASan,
#                covered by the normal run), and a short run of each fuzz target
#                (tests/fuzz), in a second build folder with
#                AddressSanitizer and UndefinedBehaviorSanitizer, where any
#                report fails the run.  Built at -O1 (faster to compile than
#                -O3, and fast enough to run), only the targets it runs, one
#                library shared by all of them.  UBSan's `alignment` and
#                `null` checks are left out: they instrument every reference
#                binding and doubled the compile time of the template-heavy
#                files (report.cpp: 29 s -> 18 s CPU; ASan alone 14 s); a
#                null dereference is still caught by ASan, and misaligned
#                access is harmless on x86-64.  Every other UBSan check
#                (integer overflow, shifts, bounds, float casts, enums,
#                bools, vptr, object size, ...) stays on.
#   make fuzz  - the fuzz targets under libFuzzer (clang), for long runs
#                (tests/fuzz/README.md)
BUILD ?= build
SAN_BUILD ?= build-san
JOBS  ?= $(shell nproc 2>/dev/null || echo 2)

FUZZ_BUILD ?= build-fuzz
SAN_FLAGS = -fsanitize=address,undefined -fno-sanitize=alignment,null -fno-sanitize-recover=all -fno-omit-frame-pointer
SAN_TARGETS = tmcert_cli tmcert_unit tmcert_crosscheck tmcert_property fuzz_scene_reader fuzz_certificate fuzz_kernels
SAN_ENV = ASAN_OPTIONS=halt_on_error=1:detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 TMCERT_SANITIZED=1
FUZZ_SECONDS ?= 15

.PHONY: all deps configure build demo test sanitize fuzz clean

all: build

deps:
	bash scripts/deps.sh

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON

build: configure
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/tmcert verify examples/octagons-collision.json; test $$? -le 2
	$(BUILD)/tmcert verify examples/octagons-near.json; test $$? -le 2

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	$(MAKE) sanitize

sanitize: deps
	cmake -S . -B $(SAN_BUILD) -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" \
	  -DBUILD_TESTING=ON -DTMCERT_FUZZ=ON -DTMCERT_FUZZ_SECONDS=$(FUZZ_SECONDS) \
	  "-DCMAKE_CXX_FLAGS=$(SAN_FLAGS)" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" \
	  "-DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=address,undefined" \
	  "-DTMCERT_PROPERTY_PARAMS=seed=20261123 max_success=25"
	cmake --build $(SAN_BUILD) -j $(JOBS) --target $(SAN_TARGETS)
	cd $(SAN_BUILD) && $(SAN_ENV) ctest --output-on-failure -j $(JOBS) \
	  -R '^(unit|crosscheck|property|cli_regression|fuzz_scene_reader|fuzz_certificate|fuzz_kernels)$$'

# libFuzzer needs clang (scripts/deps.sh installs clang and its runtime).
FUZZ_CXX ?= $(shell command -v clang++-14 || command -v clang++)
fuzz:
	bash scripts/deps.sh fuzz
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" \
	  -DCMAKE_CXX_COMPILER=$(FUZZ_CXX) -DBUILD_TESTING=ON -DTMCERT_FUZZ=ON -DTMCERT_LIBFUZZER=ON \
	  -DTMCERT_FUZZ_SECONDS=$(FUZZ_SECONDS) \
	  "-DCMAKE_CXX_FLAGS=-frounding-math -fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=all" \
	  "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined"
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz_scene_reader fuzz_certificate fuzz_kernels
	cd $(FUZZ_BUILD) && ctest --output-on-failure -L fuzz

clean:
	rm -rf $(BUILD) $(SAN_BUILD) $(FUZZ_BUILD)
