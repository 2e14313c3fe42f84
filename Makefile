# vesica: two commands set everything up.
#   make demo   install missing Debian packages, build (Release), run the demo pipeline
#   make test   same set-up, then every test through ctest: all four tiers (unit,
#               acceptance, fuzz, install) and the assertions they executed
#   make check  build, then the unit tier only (ctest -L unit): the quick loop before a commit
#   make bench  same set-up, then the benchmarks (JSON in build/bench/, table in
#               docs/benchmarks.md)
#   make install [PREFIX=/usr/local]  build, then install executables, libraries, headers,
#               the CMake package (find_package(vesica)) and the example pipelines
#   make package  build, then the Debian packages build/vesica_<version>_amd64.deb and
#               build/vesica-dev_<version>_amd64.deb (CPack)
# Everything is idempotent: a second call installs nothing and rebuilds only what changed.

BUILD_DIR ?= build
JOBS      ?= $(shell nproc)
PREFIX    ?= /usr/local
SUDO      := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

DEBIAN_PACKAGES := cmake ninja-build g++ pkg-config \
  libinsighttoolkit5-dev libgdcm-dev libvtk9-dev libcgal-dev libgmsh-dev \
  libeigen3-dev libsuitesparse-dev libmumps-seq-dev libopenblas0-pthread libassimp-dev libyaml-cpp-dev nlohmann-json3-dev \
  libcli11-dev libfmt-dev libspdlog-dev libssl-dev libgtest-dev libbenchmark-dev \
  xvfb xauth chromium snakemake python3-meshio libjs-three \
  python3-dev python3-pybind11 pybind11-dev python3-numpy python3-pytest
# zlib: core reads every gzip output back before it replaces anything
DEBIAN_PACKAGES += zlib1g-dev

# make package: dpkg-shlibdeps computes the Debian package's Depends.
DEBIAN_PACKAGES += dpkg-dev
# The compiler cache: a rebuild compiles from the cache what did not change.
DEBIAN_PACKAGES += ccache

# Extra cmake options for the first configure (e.g. CMAKE_ARGS=-DVESICA_SHARED_DIR=/data).
CMAKE_ARGS ?=
# ccache may trust a header's contents rather than its time stamps (its manual,
# "Sloppiness"): a fresh clone has every file new.
export CCACHE_SLOPPINESS ?= pch_defines,time_macros,include_file_mtime,include_file_ctime
# Paths inside the checkout hashed relative to it, so that a second checkout (a git worktree,
# a fresh clone) compiles from the cache what the first one compiled.
export CCACHE_BASEDIR ?= $(CURDIR)

.PHONY: all deps configure build build-tests demo check test bench install package format clean

all: build

# Installs only what is missing; silent when everything is present.
deps:
	@missing=$$(for p in $(DEBIAN_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "ok installed" || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "Installing Debian packages:" $$missing; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing >/dev/null; \
	fi

# ccache is the compiler launcher when it is installed (deps installs it).
$(BUILD_DIR)/build.ninja: CMakeLists.txt | deps
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release \
	  $$(command -v ccache >/dev/null && echo -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
	    -DCMAKE_C_COMPILER_LAUNCHER=ccache) $(CMAKE_ARGS) >/dev/null

configure: deps $(BUILD_DIR)/build.ninja

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	$(BUILD_DIR)/bin/vesica run pipelines/demo.yaml --workdir $(BUILD_DIR)/demo
	@echo "Demo outputs in $(BUILD_DIR)/demo; report: $(BUILD_DIR)/demo/report/index.html"

# Everything, and the readers built a second time with sanitizers for the fuzz tier (not
# part of `build`: only the full test run pays for them), in one ninja run.
build-tests: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target all vesica_fuzz

check: build
	cd $(BUILD_DIR) && ctest -L '^unit$$' --output-on-failure -j $(JOBS)

# Every tier; at the end, how many assertions the test processes executed
# (tests/support/AssertionCount.h), the figure that must not fall when tests move.
test: build-tests
	@rm -f $(BUILD_DIR)/assertions.log
	cd $(BUILD_DIR) && VESICA_ASSERTION_LOG=$$PWD/assertions.log \
	  ctest --output-on-failure -j $(JOBS); rc=$$?; \
	  cat assertions.log 2>/dev/null | \
	    awk '{ n += $$1; p++ } END { printf "%d assertions executed by %d test processes\n", n, p }'; \
	  exit $$rc

# BENCH="segment surface" runs only those benchmarks (bench/bench_NAME.sh); every run
# rewrites the table of docs/benchmarks.md.
bench: build
	bench/run.sh $(BUILD_DIR) $(BENCH)

install: build
	cmake --install $(BUILD_DIR) --prefix $(PREFIX)

package: build
	cd $(BUILD_DIR) && cpack -G DEB
	@ls $(BUILD_DIR)/*.deb

format:
	find core io segment surface mesh simulate compare pipelines tests bench \
	  \( -name '*.h' -o -name '*.cpp' \) -print0 | xargs -0 clang-format -i

clean:
	rm -rf $(BUILD_DIR)
