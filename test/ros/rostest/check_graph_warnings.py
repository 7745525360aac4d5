#!/usr/bin/python3
"""The warnings of a node about the graph around it reach /rosout
(docs/ros_interface.md, "Frames and units"). With /use_sim_time set (by
graph_warnings.test) and no /clock, a node that does not publish /clock
warns naming publish_clock:=true; a second simulator without a frame prefix
warns that another node (named by its caller id) sends its table frame, and
suggests ~frame_prefix; nodes whose frames differ, or that publish /clock,
do not warn. A brick whose tf frame would be the fixed frame is refused. The test starts the node binaries itself, after it subscribes
to /rosout, so that it misses no message."""

import os
import subprocess
import threading
import time
import unittest

import rospkg
import rospy
import rostest
from brick_stack_sim.srv import GetBricks, PlaceBrick, ResetScene
from geometry_msgs.msg import Pose
from rosgraph_msgs.msg import Log
from node_binary import PKG, node_binary_and_data


class GraphWarnings(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.binary, cls.data = node_binary_and_data()
        rospy.init_node("graph_warnings_test")
        cls.lock = threading.Lock()
        cls.warnings = []  # (node name, text) of every WARN on /rosout
        cls.subscriber = rospy.Subscriber("/rosout", Log, cls.on_log, queue_size=1000)
        cls.processes = []
        time.sleep(1.0)  # registered before any node starts

    @classmethod
    def tearDownClass(cls):
        for process in cls.processes:
            if process.poll() is None:
                process.terminate()
                process.communicate(timeout=30)

    @classmethod
    def on_log(cls, message):
        if message.level == Log.WARN:
            with cls.lock:
                cls.warnings.append((message.name, message.msg))

    def start(self, namespace, *args):
        process = subprocess.Popen([self.binary, "__ns:=" + namespace] + self.data + list(args),
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.processes.append(process)
        return process

    def warned(self, node, *words):
        with self.lock:
            return [text for name, text in self.warnings
                    if name == node and all(word in text for word in words)]

    def wait_for(self, node, words, seconds):
        end = time.time() + seconds
        while time.time() < end:
            if self.warned(node, *words):
                return True
            time.sleep(0.1)
        return bool(self.warned(node, *words))

    def test_warnings(self):
        self.assertTrue(rospy.get_param("/use_sim_time"), "graph_warnings.test sets it")
        # Sim time, nobody publishes /clock: the node says how to fix it.
        self.start("d", "_frame_prefix:=d")
        self.assertTrue(self.wait_for("/d/brick_sim", ["/use_sim_time", "publish_clock:=true"],
                                      15.0),
                        "no /clock warning from /d/brick_sim: %s" % self.warnings)
        # A publishes /clock; C has a prefix of its own: neither warns, and A
        # does not take its own frames for another's.
        self.start("a", "_publish_clock:=true")
        # C's fixed frame is c/s0, the frame a brick s0 would have under c.
        self.start("c", "_frame_prefix:=c", "_frame_id:=c/s0")
        self.check_brick_named_like_the_fixed_frame()
        time.sleep(8.0)  # past both nodes' windows
        for node in ("/a/brick_sim", "/c/brick_sim"):
            self.assertEqual(self.warned(node, "another node"), [], node)
        self.assertEqual(self.warned("/a/brick_sim", "/clock arrived"), [])
        self.assertEqual(self.warned("/c/brick_sim", "/clock arrived"), [],
                         "A publishes /clock")
        self.assertEqual(self.warned("/d/brick_sim", "another node"), [])
        # B, like A without a prefix: both name the frame 'table'.
        self.start("b")
        self.assertTrue(self.wait_for("/b/brick_sim",
                                      ["/a/brick_sim", "'table'", "~frame_prefix"], 15.0),
                        "no clash warning from /b/brick_sim: %s" % self.warnings)
        self.assertEqual(len(self.warned("/b/brick_sim", "another node")), 1, "warned once")
        self.assertEqual(self.warned("/b/brick_sim", "/clock arrived"), [])
        for process in self.processes:
            self.assertIsNone(process.poll(), "a node exited")

    def check_brick_named_like_the_fixed_frame(self):
        """Called by test_warnings while C runs: a brick whose frame would be
        the fixed frame is refused, by ~place_brick and in a scene, and the
        refusal changes nothing."""
        rospy.wait_for_service("/c/brick_sim/reset", timeout=30.0)
        place = rospy.ServiceProxy("/c/brick_sim/place_brick", PlaceBrick)
        pose = Pose()
        pose.position.x, pose.position.z, pose.orientation.w = 0.3, 0.0039, 1.0
        answer = place(id="s1", type="", pose=pose)
        self.assertTrue(answer.success, answer.message)
        pose.position.x = -0.3
        answer = place(id="s0", type="", pose=pose)
        self.assertFalse(answer.success, "brick s0 with the fixed frame c/s0 was placed")
        for word in ("s0", "c/s0", "~frame_id"):
            self.assertIn(word, answer.message)
        scene = os.path.join(rospkg.RosPack().get_path(PKG), "test", "ros", "rostest",
                             "two_bricks.yaml")
        answer = rospy.ServiceProxy("/c/brick_sim/reset", ResetScene)(scene=scene)
        self.assertFalse(answer.success, "a scene with brick s0 was played")
        self.assertIn("s0", answer.message)
        bricks = rospy.ServiceProxy("/c/brick_sim/get_bricks", GetBricks)(ids=[]).bricks
        self.assertEqual([brick.id for brick in bricks], ["s1"], "a refusal changed the world")


if __name__ == "__main__":
    rostest.rosrun(PKG, "graph_warnings", GraphWarnings)
