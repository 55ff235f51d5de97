# The two commands of the README, and what CI runs. Each installs what it needs first
# (scripts/setup.sh is idempotent), configures once and rebuilds only what changed.
#
#   make run     build the executable alone (make app), then render the built-in default scene to out/default.png
#   make test    build with warnings as errors and run every test
#   make sanitize  Debug build (synchronous GL error callback) under ASan + UBSan, all tests
#   make ci      both of the above: what .ci/run does
#   make fuzz    libFuzzer targets of the loaders, FUZZ_SECONDS (default 20) each (scripts/fuzz.sh)

BUILD_DIR ?= build
SANITIZE_DIR ?= build-sanitize
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all setup build app run test sanitize ci clean fuzz

all: build

setup:
	@./scripts/setup.sh

$(BUILD_DIR)/build.ninja: | setup
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release -DMANYLIGHTS_WERROR=ON $(CMAKE_FLAGS)

build: setup $(BUILD_DIR)/build.ninja
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The executable and the libraries it links, without the tests (31 of the build's 48 steps,
# docs/testing.md "The first run and the suite's time"): what `make run` and the measure scripts need.
app: setup $(BUILD_DIR)/build.ninja
	@echo "building only the manylights executable (make build or make test builds the tests too)"
	cmake --build $(BUILD_DIR) -j $(JOBS) --target manylights

run: app
	@mkdir -p out
	$(BUILD_DIR)/manylights render -o out/default.png --stats out/default-stats.json
	@echo "wrote out/default.png and out/default-stats.json"

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

$(SANITIZE_DIR)/build.ninja: | setup
	cmake -S . -B $(SANITIZE_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Debug -DMANYLIGHTS_WERROR=ON -DMANYLIGHTS_SANITIZE=ON $(CMAKE_FLAGS)

# LeakSanitizer runs on the tests without GL. With a GL context it cannot work: Mesa
# dlcloses its driver at exit, before the leak check, so the driver's own never-freed
# allocations show up from "<unknown module>" and no suppression can name them. Address and
# undefined-behaviour checks stay on everywhere.
SANITIZER_ENV = ASAN_OPTIONS=abort_on_error=1:detect_leaks=1 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

# The GL tiers also keep ASan's quarantine of freed memory to 16 MiB (the default is 256 MiB).
# llvmpipe's shader code allocates through posix_memalign as it runs (92% of the page faults of
# a profiled test came from there), gigabytes in a test, and with the default quarantine each
# allocation got fresh pages from the kernel: one test took 12.3 s, 8.3 s with 16 MiB and 3.6 s
# with no quarantine (docs/testing.md, "CI's time"). Use after free is still caught within the
# last 16 MiB freed; Mesa's churn recycled the default's 256 MiB many times over in a test.
sanitize: setup $(SANITIZE_DIR)/build.ninja
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && $(SANITIZER_ENV) ctest --output-on-failure -j $(JOBS) -R '^unit\.'
	cd $(SANITIZE_DIR) && $(SANITIZER_ENV) ASAN_OPTIONS=abort_on_error=1:detect_leaks=0:quarantine_size_mb=16 \
		ctest --output-on-failure -j $(JOBS) -E '^unit\.'

ci: test sanitize

FUZZ_SECONDS ?= 20
fuzz:
	./scripts/fuzz.sh $(FUZZ_SECONDS)

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) build-fuzz
