#!/usr/bin/python3
"""Starts brick_stack_sim_node with one bad private parameter at a time and
checks that it exits non-zero with a message naming that parameter; a control
run with good parameters must keep running, so the test can tell the two apart."""

import subprocess
import time
import unittest

import rostest
from node_binary import PKG, node_binary_and_data


class BadParameters(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.binary, cls.data = node_binary_and_data()
        cls.runs = 0

    def start(self, args):
        BadParameters.runs += 1
        # A node name of its own per run: its private parameters stay apart.
        name = "__name:=bad_params_%d" % BadParameters.runs
        return subprocess.Popen([self.binary, name] + self.data + args, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, universal_newlines=True)

    def check_refused(self, args, *words):
        process = self.start(args)
        try:
            output, _ = process.communicate(timeout=60)
        except subprocess.TimeoutExpired:
            process.kill()
            process.communicate()
            self.fail("node kept running with %s" % args)
        self.assertNotEqual(process.returncode, 0, "node exited 0 with %s" % args)
        for word in words:
            self.assertIn(word, output, "%s not in the output for %s:\n%s" % (word, args, output))

    def test_negative_time_step(self):
        self.check_refused(["_time_step:=-1"], "~time_step", "-1")

    def test_time_step_of_wrong_type(self):
        self.check_refused(["_time_step:=fast"], "~time_step", "fast")

    def test_zero_iterations(self):
        self.check_refused(["_solver_iterations:=0"], "~solver_iterations")

    def test_unavailable_mode(self):
        # Mode names are exact: a capitalised one is not a mode of this build.
        self.check_refused(["_stability/mode:=Equilibrium"], "~stability/mode", "not available")

    def test_unknown_mode(self):
        self.check_refused(["_stability/mode:=magic"], "~stability/mode", "magic")

    def test_bad_stability_threshold(self):
        self.check_refused(["_stability/rest_time:=-1"], "~stability/rest_time", "-1")

    def test_stability_threshold_of_wrong_type(self):
        self.check_refused(["_stability/min_margin:=wide"], "~stability/min_margin", "wide")

    def test_table_size_not_a_list(self):
        self.check_refused(["_table/size:=[1.0, 0.5, 0.2]"], "~table/size")

    def test_missing_urdf(self):
        self.check_refused(["_types_urdf:=/nonexistent/bricks.urdf"], "/nonexistent/bricks.urdf")

    def test_misspelt_parameter(self):
        # A typo must stop the node, not silently leave the default in place.
        self.check_refused(["_time_stepp:=0.002"], "~time_stepp", "not a known parameter")

    def test_misspelt_nested_parameter(self):
        self.check_refused(["_stability/rest_tme:=0.1"], "~stability/rest_tme",
                           "not a known parameter")

    def test_fixed_frame_named_like_the_table_frame(self):
        # tf2 would refuse the table frame as its own parent (TF_SELF_TRANSFORM).
        self.check_refused(["_frame_id:=table"], "~frame_id", "table")
        self.check_refused(["_frame_id:=sim1/table", "_frame_prefix:=sim1"], "~frame_id",
                           "sim1/table")

    def test_unknown_initial_scene(self):
        self.check_refused(["_scene:=no_such_scene_5678"], "~scene", "no_such_scene_5678")

    def test_scene_brick_cap_out_of_range(self):
        self.check_refused(["_scene_max_bricks:=0"], "~scene_max_bricks", "must be in [1, 1000000]")

    def test_legend_scale_out_of_range(self):
        self.check_refused(["_legend_scale:=0"], "~legend_scale", "must be in (0, 100]")

    def test_initial_scene_over_the_brick_cap(self):
        # tower10 is 10 layers of two bricks: counted, not built, and refused.
        self.check_refused(["_scene:=tower10", "_scene_max_bricks:=15"], "~scene",
                           "generator 1 (tower) would bring the scene to 20 bricks: at most 15 "
                           "(scene_max_bricks)")

    def test_good_parameters_keep_running(self):
        process = self.start(["_time_step:=0.001"])
        try:
            time.sleep(3.0)
            self.assertIsNone(process.poll(), "node with good parameters exited:\n%s"
                              % (process.communicate()[0] if process.poll() is not None else ""))
        finally:
            if process.poll() is None:
                process.terminate()
                process.communicate(timeout=30)


if __name__ == "__main__":
    rostest.rosrun(PKG, "bad_parameters", BadParameters)
