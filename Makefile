# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Quick start on a fresh Debian/Ubuntu machine:
#   make evaluate   # installs dependencies, builds, runs the main job, writes results/
#   make test       # installs dependencies, builds, runs every test

BUILD_DIR ?= build
RESULTS_DIR ?= results
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=
DEBIAN_PACKAGES = g++ make cmake ccache libcgal-dev libcgal-demo libeigen3-dev libboost-dev \
                  libgmp-dev libmpfr-dev catch2 python3-matplotlib python3-numpy doxygen parallel
CGAL_DATA_ARCHIVE = /usr/share/doc/libcgal-dev/data.tar.gz
CORPUS_DIR = $(BUILD_DIR)/cgal-data
TOOL = $(BUILD_DIR)/tools/sigmoid-neighborhoods/sigmoid-neighborhoods

.PHONY: all deps configure build test evaluate corpus clean

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
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The embedded default corpus: the public data of Debian's libcgal-demo.
corpus: deps
	@mkdir -p $(CORPUS_DIR)
	@[ -f $(CORPUS_DIR)/.extracted ] || { tar -xzf $(CGAL_DATA_ARCHIVE) -C $(CORPUS_DIR) && touch $(CORPUS_DIR)/.extracted; }

# The main job: the evaluation of the embedded default corpus, CGAL's meshes as a clean repository
# and its point sets with normals as a scanned one, then the report with Figure 3 on the fandisk.
evaluate: build corpus
	@mkdir -p $(RESULTS_DIR)
	$(TOOL) evaluate $(CORPUS_DIR)/data/meshes -o $(RESULTS_DIR)/clean --repository "CGAL meshes"
	$(TOOL) evaluate $(CORPUS_DIR)/data/points_3 -o $(RESULTS_DIR)/scanned --repository "CGAL point sets" \
	  --only-with-normals
	$(TOOL) report $(RESULTS_DIR)/clean $(RESULTS_DIR)/scanned -o $(RESULTS_DIR) \
	  --figure-model $(CORPUS_DIR)/data/meshes/fandisk.off
	$(TOOL) optimal $(CORPUS_DIR)/data/meshes/fandisk.off -o $(RESULTS_DIR)/fandisk_optimal.csv \
	  --ply $(RESULTS_DIR)/fandisk_optimal.ply
	@echo "Report: $(RESULTS_DIR)/report.md"

clean:
	rm -rf $(BUILD_DIR)
