# Thin wrapper: the two set-up commands of the README.
#   make demo  - install missing Debian packages, build, verify a bundled example
#   make test  - install missing Debian packages, build, run the whole test suite
BUILD ?= build
JOBS  ?= $(shell nproc 2>/dev/null || echo 2)

.PHONY: all deps configure build demo test clean

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

clean:
	rm -rf $(BUILD)
