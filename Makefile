# The two commands of the README: `make demo` and `make test`. Each installs the
# Debian packages it needs when missing, builds in .catkin_ws and runs.
# The scripts are development scripts run from the source tree with bash (not
# executable): they build a workspace, so they have no place in an install space.
SHELL := /bin/bash
.PHONY: deps build test test-cluster check-install demo demo-gui bench bench-quick stress sanitize clean

deps:
	@bash scripts/install_deps.sh build

build: deps
	@bash scripts/build.sh

# The test set adds what stack_sim_sweep's tests run: GNU parallel, PyYAML,
# and Slurm with munge for the cluster test.
test:
	@bash scripts/install_deps.sh test
	@bash scripts/run_tests.sh

# stack_sim_sweep on Slurm (docs/sweeps.md): installs Slurm and munge, starts
# the single-node Slurm of scripts/start_slurm.sh, runs the cluster test
# (where it cannot start, a failure here, not a skip) and stops Slurm again.
test-cluster:
	@bash scripts/install_deps.sh cluster
	@bash scripts/build.sh
	@status=0; bash scripts/start_slurm.sh start >/dev/null || status=$$?; \
	if ((status == 0)); then \
	  source scripts/env.sh && source .catkin_ws/devel/setup.bash \
	    && /usr/bin/python3 test/sweep/test_sweep_cluster.py --require \
	       --junit .catkin_ws/test_cluster/sweep_cluster.xml \
	       --program .catkin_ws/devel/lib/brick_stack_sim/stack_sim_sweep; \
	  status=$$?; \
	fi; \
	bash scripts/start_slurm.sh stop; exit $$status

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
