# Thin wrapper: the two set-up commands of the README.
#   make demo  - install missing Debian packages, build, verify a bundled example
#   make test  - install missing Debian packages, build, run the whole test suite
#   make sanitize - the unit, crosscheck, property (fewer cases) and CLI suites
#                again in a second build folder with AddressSanitizer and
#                UndefinedBehaviorSanitizer, where any report fails the run
#                (not part of make test: its build alone takes longer than
#                the whole of make test on 2 cores)
BUILD ?= build
SAN_BUILD ?= build-san
JOBS  ?= $(shell nproc 2>/dev/null || echo 2)

SAN_FLAGS = -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
SAN_TARGETS = tmcert_cli tmcert_unit tmcert_crosscheck tmcert_property
SAN_ENV = ASAN_OPTIONS=halt_on_error=1:detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1

.PHONY: all deps configure build demo test sanitize clean

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

sanitize: deps
	cmake -S . -B $(SAN_BUILD) -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON \
	  "-DCMAKE_CXX_FLAGS=$(SAN_FLAGS)" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" \
	  "-DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=address,undefined" \
	  "-DTMCERT_PROPERTY_PARAMS=seed=20261123 max_success=25"
	cmake --build $(SAN_BUILD) -j $(JOBS) --target $(SAN_TARGETS)
	cd $(SAN_BUILD) && $(SAN_ENV) ctest --output-on-failure -j $(JOBS) -R '^(unit|crosscheck|property|cli_regression)$$'

clean:
	rm -rf $(BUILD) $(SAN_BUILD)
