# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Quick start on a fresh Debian/Ubuntu machine:
#   make evaluate   # installs dependencies, builds, runs the main job, writes results/
#   make test       # installs dependencies, builds, builds the manual, runs every test
#   make doc        # the manuals only: $(BUILD_DIR)/doc/html/index.html, $(BUILD_DIR)/doc/lidar_io/html/
#   make denoising  # the denoiser against CGAL's smoothing: $(RESULTS_DIR)/denoising/
#   make classification  # feature sets for semantic classification of lidar: $(RESULTS_DIR)/classification/
#   make python     # the Python module, installed into $(PYTHON_VENV) (a venv that sees Debian's numpy)

BUILD_DIR ?= build
RESULTS_DIR ?= results
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=
# What `make evaluate` needs: the compiler, CGAL and its dependencies, JSON, and matplotlib for the
# report's figures.
EVALUATE_PACKAGES = g++ make cmake ccache libcgal-dev libcgal-demo libeigen3-dev libboost-dev \
                    libgmp-dev libmpfr-dev libboost-serialization-dev libboost-iostreams-dev zlib1g-dev \
                    nlohmann-json3-dev python3-matplotlib python3-numpy libtbb-dev
# and for everything else (the tests, the manual, the Python module, the scale-out recipes)
DEBIAN_PACKAGES = $(EVALUATE_PACKAGES) catch2 doxygen parallel \
                  python3-dev python3-venv python3-setuptools python3-pytest pybind11-dev python3-pybind11 \
                  libnanoflann-dev
# Only for `make test`: the viewer test opens the tool's PLY files in CloudCompare (headless); the
# Python examples' tests use Open3D and scikit-learn.
TEST_PACKAGES = cloudcompare python3-open3d python3-sklearn
CGAL_DATA_ARCHIVE = /usr/share/doc/libcgal-dev/data.tar.gz
CORPUS_DIR = $(BUILD_DIR)/cgal-data
TOOL = $(BUILD_DIR)/tools/sigmoid-neighborhoods/sigmoid-neighborhoods

.PHONY: all deps deps-evaluate test-deps configure build build-tool doc test sanitize fuzz fuzz-evaluation fuzz-laz evaluate corpus denoising classification python clean

all: build

# Installs only what is missing; uses sudo when not root.
deps:
	@missing=""; \
	for p in $(DEBIAN_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "Installing:$$missing"; \
	  if [ "$$(id -u)" -eq 0 ]; then SUDO=""; else SUDO="sudo"; fi; \
	  $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq --no-install-recommends $$missing; \
	fi

configure: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# Only what the main job runs: the tool (its commands and the readers' library), configured without
# the tests (catch2 and the test packages are not needed yet); `make build` or `make test` later
# configures the same folder with them and reuses the tool as built.
deps-evaluate:
	@$(MAKE) --no-print-directory deps DEBIAN_PACKAGES="$(EVALUATE_PACKAGES)"

build-tool: deps-evaluate
	@if [ -f $(BUILD_DIR)/CMakeCache.txt ]; then cmake -S . -B $(BUILD_DIR) > /dev/null; \
	else cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF $(CMAKE_FLAGS); fi
	cmake --build $(BUILD_DIR) --target sigmoid-neighborhoods -j $(JOBS)

# The manual (Doxygen, doc/Sigmoid_neighborhoods/), written to $(BUILD_DIR)/doc/html/. Fails when
# doxygen reports anything: every warning (an undocumented public name, a broken reference) is an error.
DOC_DIR = $(BUILD_DIR)/doc
doc: deps
	@rm -rf $(DOC_DIR)/html && mkdir -p $(DOC_DIR)
	@( cat doc/Sigmoid_neighborhoods/Doxyfile; echo "OUTPUT_DIRECTORY = $(DOC_DIR)" ) | doxygen - 2> $(DOC_DIR)/warnings.log; \
	status=$$?; \
	if [ $$status -ne 0 ] || [ -s $(DOC_DIR)/warnings.log ]; then \
	  cat $(DOC_DIR)/warnings.log >&2; \
	  echo "make doc: doxygen failed or warned (exit code $$status, $$(grep -c . $(DOC_DIR)/warnings.log) lines above)" >&2; \
	  exit 1; \
	fi
	@mkdir -p $(DOC_DIR)/lidar_io && rm -rf $(DOC_DIR)/lidar_io/html
	@( cat lidar_io/doc/Doxyfile; echo "OUTPUT_DIRECTORY = $(DOC_DIR)/lidar_io" ) | doxygen - 2> $(DOC_DIR)/lidar_io/warnings.log; \
	status=$$?; \
	if [ $$status -ne 0 ] || [ -s $(DOC_DIR)/lidar_io/warnings.log ]; then \
	  cat $(DOC_DIR)/lidar_io/warnings.log >&2; \
	  echo "make doc: doxygen failed or warned on lidar_io (exit code $$status)" >&2; \
	  exit 1; \
	fi
	@echo "Manuals: $(DOC_DIR)/html/index.html, $(DOC_DIR)/lidar_io/html/index.html (0 doxygen warnings)"

test-deps:
	@$(MAKE) --no-print-directory deps DEBIAN_PACKAGES="$(TEST_PACKAGES)"

test: build doc test-deps
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The test suite built with AddressSanitizer and UndefinedBehaviorSanitizer, in its own folder:
# the library's and the tool's tests, without the examples (built and run by 'make test'), the
# long end-to-end reruns of code the tests cover (label long: the denoising tables, the tiled
# classification; the tiles' halos on LAS are the Catch2 [catalog] tests') and the tests that only
# compile (label compile_only), so that it and 'make test' fit in CI's time. -O2 as the release
# build, and line tables only (-g1): file and line in the sanitizers' stack traces, without the
# full debug information of CGAL's templates, which is slow to write and link.
SANITIZE_DIR ?= build-sanitize
sanitize: deps
	cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
	  -DSIGMOID_NEIGHBORHOODS_BUILD_BENCHMARKS=OFF \
	  -DSIGMOID_NEIGHBORHOODS_BUILD_PYTHON=OFF -DSIGMOID_NEIGHBORHOODS_BUILD_EXAMPLES=OFF \
	  -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && ASAN_OPTIONS=detect_leaks=0 ctest --output-on-failure -j $(JOBS) -LE 'long|compile_only'

# The libFuzzer target over reading a file and the optimal search (test/fuzz/README.md), built with
# clang, AddressSanitizer and UndefinedBehaviorSanitizer in its own folder, run for FUZZ_SECONDS on
# $(FUZZ_DIR)/corpus (the seeds, and what earlier runs added); failing inputs go to $(FUZZ_DIR)/artifacts/.
# The tool stays configured (the test folder refers to it) but only the fuzzer is built.
FUZZ_DIR ?= build-fuzz
FUZZ_SECONDS ?= 600
fuzz: deps
	@command -v clang++ > /dev/null || { echo "make fuzz needs clang and libFuzzer (Debian: clang libclang-rt-dev)" >&2; exit 1; }
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DSIGMOID_NEIGHBORHOODS_BUILD_FUZZER=ON -DSIGMOID_NEIGHBORHOODS_BUILD_EXAMPLES=OFF \
	  -DSIGMOID_NEIGHBORHOODS_BUILD_BENCHMARKS=OFF
	cmake --build $(FUZZ_DIR) --target fuzz_read_and_optimal -j $(JOBS)
	@mkdir -p $(FUZZ_DIR)/corpus $(FUZZ_DIR)/artifacts $(FUZZ_DIR)/tmp && rm -f $(FUZZ_DIR)/tmp/*
	cp test/fuzz/seeds/* $(FUZZ_DIR)/corpus/
	@# LAZ seeds: the small files of ../shared/data/laz, behind a selector byte (never copied into the project)
	@if [ -d ../shared/data/laz ]; then for f in ../shared/data/laz/*.laz; do \
	  [ "$$(stat -c %s "$$f")" -le 65536 ] && { printf '\000'; cat "$$f"; } > $(FUZZ_DIR)/corpus/laz_$$(basename "$$f"); \
	done; true; fi
	TMPDIR=$(CURDIR)/$(FUZZ_DIR)/tmp ASAN_OPTIONS=quarantine_size_mb=64 \
	UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:suppressions=$(CURDIR)/test/fuzz/ubsan_suppressions.txt \
	  $(FUZZ_DIR)/test/fuzz/fuzz_read_and_optimal $(FUZZ_DIR)/corpus -max_total_time=$(FUZZ_SECONDS) \
	  -max_len=1048576 -timeout=10 -rss_limit_mb=512 -malloc_limit_mb=256 -artifact_prefix=$(CURDIR)/$(FUZZ_DIR)/artifacts/ \
	  -print_final_stats=1

# The second fuzz target: the readers of the evaluation files (model files, summary.json, failures.json),
# in the same folder, on $(FUZZ_DIR)/evaluation_corpus; failing inputs go to $(FUZZ_DIR)/artifacts/.
fuzz-evaluation: deps
	@command -v clang++ > /dev/null || { echo "make fuzz-evaluation needs clang and libFuzzer (Debian: clang libclang-rt-dev)" >&2; exit 1; }
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DSIGMOID_NEIGHBORHOODS_BUILD_FUZZER=ON -DSIGMOID_NEIGHBORHOODS_BUILD_EXAMPLES=OFF \
	  -DSIGMOID_NEIGHBORHOODS_BUILD_BENCHMARKS=OFF
	cmake --build $(FUZZ_DIR) --target fuzz_evaluation_files -j $(JOBS)
	@mkdir -p $(FUZZ_DIR)/evaluation_corpus $(FUZZ_DIR)/artifacts $(FUZZ_DIR)/tmp
	cp test/fuzz/evaluation_seeds/* $(FUZZ_DIR)/evaluation_corpus/
	TMPDIR=$(CURDIR)/$(FUZZ_DIR)/tmp ASAN_OPTIONS=quarantine_size_mb=64 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
	  $(FUZZ_DIR)/test/fuzz/fuzz_evaluation_files $(FUZZ_DIR)/evaluation_corpus -max_total_time=$(FUZZ_SECONDS) \
	  -max_len=1048576 -timeout=5 -rss_limit_mb=512 -malloc_limit_mb=256 -artifact_prefix=$(CURDIR)/$(FUZZ_DIR)/artifacts/ \
	  -print_final_stats=1

# The third fuzz target: the LAS and LAZ readers alone (test/fuzz/fuzz_laz.cpp), on the LAZ files of
# ../shared/data/laz up to 64 KiB (read, never copied into the project) and what earlier runs added.
fuzz-laz: deps
	@command -v clang++ > /dev/null || { echo "make fuzz-laz needs clang and libFuzzer (Debian: clang libclang-rt-dev)" >&2; exit 1; }
	@[ -d ../shared/data/laz ] || { echo "make fuzz-laz needs ../shared/data/laz for its seeds" >&2; exit 1; }
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DSIGMOID_NEIGHBORHOODS_BUILD_FUZZER=ON -DSIGMOID_NEIGHBORHOODS_BUILD_EXAMPLES=OFF \
	  -DSIGMOID_NEIGHBORHOODS_BUILD_BENCHMARKS=OFF
	cmake --build $(FUZZ_DIR) --target fuzz_laz -j $(JOBS)
	@mkdir -p $(FUZZ_DIR)/laz_corpus $(FUZZ_DIR)/artifacts
	@for f in ../shared/data/laz/*.laz; do [ "$$(stat -c %s "$$f")" -le 65536 ] && cp "$$f" $(FUZZ_DIR)/laz_corpus/; done; true
	ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
	  $(FUZZ_DIR)/test/fuzz/fuzz_laz $(FUZZ_DIR)/laz_corpus -max_total_time=$(FUZZ_SECONDS) \
	  -max_len=1048576 -timeout=10 -rss_limit_mb=1024 -malloc_limit_mb=512 -artifact_prefix=$(CURDIR)/$(FUZZ_DIR)/artifacts/ \
	  -print_final_stats=1

# The Python module (python/), installed without network into a virtual environment on Debian's
# /usr/bin/python3 (which sees Debian's numpy): `$(PYTHON_VENV)/bin/python -c "import sigmoid_neighborhoods"`.
PYTHON_VENV ?= .venv
python: deps
	/usr/bin/python3 -m venv --system-site-packages $(PYTHON_VENV)
	NPY_NUM_BUILD_JOBS=$(JOBS) $(PYTHON_VENV)/bin/pip install --no-build-isolation --no-index --no-deps ./python
	$(PYTHON_VENV)/bin/python -c "import sigmoid_neighborhoods as sn; print('sigmoid_neighborhoods', sn.__version__, 'in $(PYTHON_VENV)')"

# The embedded default corpus: the public data of Debian's libcgal-demo.
corpus: deps-evaluate
	@mkdir -p $(CORPUS_DIR)
	@[ -f $(CORPUS_DIR)/.extracted ] || { tar -xzf $(CGAL_DATA_ARCHIVE) -C $(CORPUS_DIR) && touch $(CORPUS_DIR)/.extracted; }

# The main job: the evaluation of the embedded default corpus, CGAL's meshes as a clean repository
# and all its point sets as a scanned one (normals estimated where a file has none), then the report
# with Figure 3 on the fandisk.
evaluate: build-tool corpus
	@mkdir -p $(RESULTS_DIR)
	$(TOOL) evaluate $(CORPUS_DIR)/data/meshes -o $(RESULTS_DIR)/clean --repository "CGAL meshes"
	$(TOOL) evaluate $(CORPUS_DIR)/data/points_3 -o $(RESULTS_DIR)/scanned --repository "CGAL point sets"
	$(TOOL) report $(RESULTS_DIR)/clean $(RESULTS_DIR)/scanned -o $(RESULTS_DIR) \
	  --figure-model $(CORPUS_DIR)/data/meshes/fandisk.off
	$(TOOL) optimal $(CORPUS_DIR)/data/meshes/fandisk.off -o $(RESULTS_DIR)/fandisk_optimal.csv \
	  --ply $(RESULTS_DIR)/fandisk_optimal.ply
	$(TOOL) denoise-experiment -o $(RESULTS_DIR)/table4 --seed 1 --fandisk $(CORPUS_DIR)/data/meshes/fandisk.off
	@echo "Report: $(RESULTS_DIR)/report.md; the denoising experiment: $(RESULTS_DIR)/table4/table4.md"

# The point-set denoising comparison (the package against CGAL's smoothing) on every model found:
# $(RESULTS_DIR)/denoising/denoising.md, .csv and .png. About a quarter of an hour on one thread.
denoising: build
	@mkdir -p $(RESULTS_DIR)
	$(TOOL) denoise-comparison -o $(RESULTS_DIR)/denoising --figure-model fandisk --seed 1

# Semantic classification of the IGN LiDAR HD tiles of ../shared/data/labeled (train on the four
# western tiles, test on the two eastern ones): every feature set in 10 feature orders, with and
# without graph-cut; $(RESULTS_DIR)/classification/experiment.md.
LABELED_DIR ?= ../shared/data/labeled
IGN = $(LABELED_DIR)/ign_lidarhd_
classification: build
	@[ -d $(LABELED_DIR) ] || { echo "make classification needs $(LABELED_DIR) (the labeled IGN tiles)" >&2; exit 1; }
	@mkdir -p $(RESULTS_DIR)
	$(TOOL) classify experiment -o $(RESULTS_DIR)/classification \
	  --train $(IGN)77050_627755.las,$(IGN)77050_627760.las,$(IGN)77055_627755.las,$(IGN)77055_627760.las \
	  --test $(IGN)77060_627755.las,$(IGN)77060_627760.las

clean:
	rm -rf $(BUILD_DIR)
