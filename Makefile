# The two commands of the README: `make demo` and `make test`. Each installs the
# Debian packages it needs when missing, builds in .catkin_ws and runs.
SHELL := /bin/bash
.PHONY: deps build test demo demo-gui bench bench-quick stress clean

deps:
	@scripts/install_deps.sh build

build: deps
	@scripts/build.sh

test: deps
	@scripts/run_tests.sh

demo: deps
	@scripts/run_demo.sh $(ARGS)

demo-gui:
	@scripts/install_deps.sh gui
	@scripts/run_demo.sh gui:=true $(ARGS)

bench-quick:
	@scripts/install_deps.sh bench
	@scripts/run_bench.sh quick

bench:
	@scripts/install_deps.sh bench
	@scripts/run_bench.sh full

stress: deps
	@scripts/run_stress.sh

clean:
	rm -rf .catkin_ws
