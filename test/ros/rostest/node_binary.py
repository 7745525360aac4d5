"""The simulator's binary and the data parameters it needs, for the python
tests that start brick_stack_sim_node themselves (each on its own terms)."""
import os

import rospkg
from roslib.packages import find_node

PKG = "brick_stack_sim"


def node_binary_and_data():
    """(path of brick_stack_sim_node, [the private parameters naming the
    package's brick types and materials])."""
    found = find_node(PKG, "brick_stack_sim_node")
    assert found, "brick_stack_sim_node not built"
    share = rospkg.RosPack().get_path(PKG)
    return found[0], [
        "_types_urdf:=" + os.path.join(share, "urdf", "bricks.urdf"),
        "_materials_yaml:=" + os.path.join(share, "config", "bricks.yaml"),
    ]
