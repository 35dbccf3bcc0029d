"""The 3-D viewer page (`amp view`, amp.viewer_page), its data decoded here with Python's own base64
and struct, independently of the C++ that wrote it: the robot's poses at start and goal are the
problem's start and goal, the path's trace joins them, every mesh is well formed; and the Python
call writes the page the command writes."""
import base64
import json
import math
import os
import pathlib
import re
import struct
import subprocess

import pytest

import amp

PROBLEMS = pathlib.Path(os.environ["AMP_SOURCE_DIR"]) / "problems"


def page_data(html):
    scene = re.search(r'<script id="amp-scene" type="application/json">(.*?)</script>', html, re.S).group(1)
    data = re.search(r'<script id="amp-data" type="application/octet-stream">(.*?)</script>', html, re.S).group(1)
    return json.loads(scene), base64.b64decode(data.strip())


def floats(buf, offset, count):
    return struct.unpack_from("<%df" % count, buf, offset)


def check_meshes(meta, buf):
    for part in meta["obstacles"] + meta["links"]:
        (v_at, v_count), (t_at, t_count) = part["vertices"], part["triangles"]
        corners = struct.unpack_from("<%dI" % (3 * t_count), buf, t_at)
        assert all(c < v_count for c in corners)
        assert v_at + 12 * v_count <= len(buf) and t_at + 12 * t_count <= len(buf)


def same_rotation(q1, q2):  # q and -q are the same rotation
    return abs(abs(sum(a * b for a, b in zip(q1, q2))) - 1.0) < 1e-5


def test_rigid_body_page_poses_the_robot_at_start_and_goal_and_plays_the_path():
    problem = amp.load_problem(str(PROBLEMS / "walls3d.yaml"))
    record, path = amp.plan(problem, planner="prm", seed=1)
    assert record["status"] == "solved"
    html = amp.viewer_page(problem, [list(s) for s in path], title="walls", subtitle="prm, seed 1")
    assert "certified collision-free along its whole length" in html
    meta, buf = page_data(html)
    check_meshes(meta, buf)
    assert [link["name"] for link in meta["links"]] == ["body"]
    assert meta["flat"] is False
    for key, state in (("start", problem.start), ("goal", problem.goal)):
        pose = floats(buf, meta[key], 7)
        assert list(pose[:3]) == pytest.approx(state[:3], abs=1e-4)
        assert same_rotation(pose[3:], state[3:])
    frames = meta["poses"]["frames"]
    assert frames >= len(path)
    first = floats(buf, meta["poses"]["offset"], 7)
    last = floats(buf, meta["poses"]["offset"] + 28 * (frames - 1), 7)
    assert list(first[:3]) == pytest.approx(problem.start[:3], abs=1e-4)
    assert list(last[:3]) == pytest.approx(problem.goal[:3], abs=1e-4)
    at, count = meta["trace"]
    assert count == frames
    trace = floats(buf, at, 3 * count)
    assert list(trace[:3]) == pytest.approx(problem.start[:3], abs=1e-4)
    assert list(trace[-3:]) == pytest.approx(problem.goal[:3], abs=1e-4)
    # Consecutive frames are close: no frame jumps along the path.
    steps = [math.dist(trace[3 * i:3 * i + 3], trace[3 * i + 3:3 * i + 6]) for i in range(count - 1)]
    assert max(steps) <= 3 * record["path_length"] / (frames - 1)


def test_a_flat_world_is_lifted_with_its_robot_turned_about_z():
    problem = amp.load_problem(str(PROBLEMS / "hook.yaml"))
    meta, buf = page_data(amp.viewer_page(problem))
    check_meshes(meta, buf)
    assert meta["flat"] is True
    assert meta["poses"]["frames"] == 1
    assert "No path: the robot is shown at the start" in "".join(meta["notes"])
    # One state, turned: the robot's pose at it is the state lifted to z = 0, turned about z.
    state = [70.0, 10.0, 0.7]
    meta, buf = page_data(amp.viewer_page(problem, [state]))
    x, y, z, qx, qy, qz, qw = floats(buf, meta["poses"]["offset"], 7)
    assert (x, y, z) == pytest.approx((state[0], state[1], 0.0), abs=1e-4)
    assert (qx, qy) == pytest.approx((0.0, 0.0), abs=1e-6)
    assert same_rotation((qz, qw), (math.sin(state[2] / 2), math.cos(state[2] / 2)))


def test_python_writes_the_page_the_command_writes(tmp_path):
    problem_file = PROBLEMS / "walls3d.yaml"
    problem = amp.load_problem(str(problem_file))
    _, path = amp.plan(problem, planner="prm", seed=2)
    path_file = tmp_path / "w.path"
    path_file.write_text("".join(" ".join(repr(float(v)) for v in s) + "\n" for s in path))
    out = tmp_path / "w.html"
    subprocess.run([os.environ["AMP_CLI"], "view", str(problem_file), "--path", str(path_file), "-o", str(out)],
                   check=True, capture_output=True)
    from_python = amp.viewer_page(problem, [list(s) for s in path], subtitle="path from " + str(path_file))
    assert out.read_text() == from_python


def test_a_path_of_the_wrong_size_is_refused():
    problem = amp.load_problem(str(PROBLEMS / "walls3d.yaml"))
    with pytest.raises(amp.Error, match="a state has 3 values, the problem's space 7"):
        amp.viewer_page(problem, [[1.0, 2.0, 3.0]])
