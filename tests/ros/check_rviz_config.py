#!/usr/bin/env python3
"""The RViz config shows what relmap_ros_bridge publishes, without a screen.

Loads robot_adapter/ros/launch/relmap.launch as roslaunch would (its node, name and
parameters), runs that node for real (a rosmaster on a loopback port, a relmap-server),
asks the master which topics the node publishes and with which types, and parses the
.rviz YAML: every display's topic must be one the node publishes with the type the
display shows (or the launch file's camera topic), and every map the node publishes
(PointCloud2, PoseStamped, Marker) must have a display.

usage: check_rviz_config.py PACKAGE_DIR SERVER_BINARY
PACKAGE_DIR is the build's relmap_ros package (build/robot_adapter/ros).
"""
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time

import yaml

# RViz display classes and the message type each shows.
DISPLAY_TYPES = {
    "rviz/PointCloud2": "sensor_msgs/PointCloud2",
    "rviz/Pose": "geometry_msgs/PoseStamped",
    "rviz/Marker": "visualization_msgs/Marker",
}


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(predicate, seconds, what, log_path):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if predicate():
            return
        time.sleep(0.05)
    with open(log_path) as log:
        tail = log.read()[-4000:]
    sys.exit(f"check_rviz_config: {what} within {seconds} s; the processes said:\n{tail}")


def rviz_topics(path):
    """(display name, class, topic) of every display with a topic."""
    with open(path) as f:
        config = yaml.safe_load(f)
    displays = config["Visualization Manager"]["Displays"]
    fixed_frame = config["Visualization Manager"]["Global Options"]["Fixed Frame"]
    if not fixed_frame:
        sys.exit(f"check_rviz_config: {path} has no Fixed Frame")
    found = []
    for display in displays:
        topic = display.get("Topic") or display.get("Marker Topic")
        if topic:
            found.append((display["Name"], display["Class"], topic))
    return found


def main():
    work = tempfile.mkdtemp(prefix="relmap-rviz-check-")
    try:
        check(sys.argv[1], sys.argv[2], work)
    finally:
        shutil.rmtree(work, ignore_errors=True)


def check(package_dir, server_binary, work):
    os.environ["ROS_PACKAGE_PATH"] = package_dir + os.pathsep + os.environ.get("ROS_PACKAGE_PATH", "")
    os.environ["ROS_HOME"] = work
    port = free_port()
    os.environ["ROS_MASTER_URI"] = f"http://127.0.0.1:{port}"
    os.environ["ROS_HOSTNAME"] = "127.0.0.1"
    import rosgraph
    import roslaunch.config
    import roslib.packages

    launch = os.path.join(package_dir, "launch", "relmap.launch")
    rviz = os.path.join(package_dir, "rviz", "relmap.rviz")
    sys.argv = [sys.argv[0]]  # roslaunch reads name:=value arguments from here
    config = roslaunch.config.load_config_default([launch], None)
    bridges = [n for n in config.nodes if n.package == "relmap_ros" and n.type == "relmap_ros_bridge"]
    if len(bridges) != 1:
        sys.exit(f"check_rviz_config: {launch} has {len(bridges)} relmap_ros_bridge nodes, not 1")
    bridge = bridges[0]
    name = rosgraph.names.ns_join(bridge.namespace, bridge.name)
    executable = roslib.packages.find_node("relmap_ros", "relmap_ros_bridge")[0]
    camera_topic = config.params[name + "/cloud_topic"].value

    children = []
    log_path = os.path.join(work, "processes.log")
    log = open(log_path, "w")
    try:
        children.append(subprocess.Popen(["rosmaster", "--core", "-p", str(port)], stdout=log, stderr=log))
        master = rosgraph.Master("/check_rviz_config")
        wait_for(master.is_online, 20, "rosmaster did not come up", log_path)
        port_file = os.path.join(work, "port")
        children.append(subprocess.Popen([server_binary, "--listen", "127.0.0.1:0", "--port-file", port_file],
                                         stdout=log, stderr=log))
        wait_for(lambda: os.path.exists(port_file) and open(port_file).read().strip(), 20,
                 "relmap-server did not write its port", log_path)
        for key, param in config.params.items():
            master.setParam(key, param.value)
        master.setParam(name + "/server", "127.0.0.1:" + open(port_file).read().strip())
        children.append(subprocess.Popen([executable, "__name:=" + bridge.name], stdout=log, stderr=log))

        def advertised():
            try:
                master.lookupService(name + "/post_outcome")
                return True
            except rosgraph.MasterError:
                return False

        wait_for(advertised, 20, f"{name} did not advertise post_outcome", log_path)
        state = master.getSystemState()[0]  # publishers: [topic, [nodes]]
        types = dict(master.getTopicTypes())
        published = {topic: types[topic] for topic, nodes in state if name in nodes}
    finally:
        for child in reversed(children):
            child.terminate()
            child.wait(timeout=15)
        log.close()

    errors = []
    shown = set()
    for display, display_class, topic in rviz_topics(rviz):
        expected = DISPLAY_TYPES.get(display_class)
        if expected is None:
            errors.append(f"display {display}: class {display_class} is not one this check knows")
        elif topic == camera_topic:
            if expected != "sensor_msgs/PointCloud2":
                errors.append(f"display {display}: the camera topic shown as {display_class}")
        elif topic not in published:
            errors.append(f"display {display}: {topic} is not published by {name} "
                          f"(it publishes {sorted(published)})")
        elif published[topic] != expected:
            errors.append(f"display {display}: {topic} is {published[topic]}, {display_class} shows {expected}")
        shown.add(topic)
    for topic, message_type in published.items():
        if message_type in DISPLAY_TYPES.values() and topic not in shown:
            errors.append(f"{name} publishes {topic} ({message_type}), which no display shows")
    if errors:
        sys.exit("check_rviz_config:\n  " + "\n  ".join(errors))
    maps = sorted(t for t, m in published.items() if m in DISPLAY_TYPES.values())
    print(f"check_rviz_config: {rviz} shows {', '.join(maps)} as {name} publishes them")


if __name__ == "__main__":
    main()
