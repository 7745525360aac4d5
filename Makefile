# The two commands of the README: `make demo` and `make test`. Each installs the
# Debian packages it needs when missing, builds in .catkin_ws and runs.
# The scripts are development scripts run from the source tree with bash (not
# executable): they build a workspace, so they have no place in an install space.
SHELL := /bin/bash
.PHONY: deps build test check-install demo demo-gui bench bench-quick stress sanitize clean

deps:
	@bash scripts/install_deps.sh build

build: deps
	@bash scripts/build.sh

test: deps
	@bash scripts/run_tests.sh

# make test runs it too; alone: install and run from the install space.
check-install: deps
	@bash scripts/check_install.sh

demo: deps
	@bash scripts/run_demo.sh $(ARGS)

demo-gui:
	@bash scripts/install_deps.sh gui
	@bash scripts/run_demo.sh gui:=true $(ARGS)

bench-quick:
	@bash scripts/install_deps.sh bench
	@bash scripts/run_bench.sh quick

bench:
	@bash scripts/install_deps.sh bench
	@bash scripts/run_bench.sh full

stress: deps
	@bash scripts/run_stress.sh

# All the tests under ASan+UBSan, then under TSan, each in its own workspace;
# one variant alone: make sanitize VARIANTS=thread
sanitize: deps
	@bash scripts/run_sanitize.sh $(VARIANTS)

clean:
	rm -rf .catkin_ws .catkin_ws_asan .catkin_ws_tsan
