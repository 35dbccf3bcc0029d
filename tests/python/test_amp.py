"""The Python module: a problem loaded, planned and checked; errors as amp.Error; bench; navigation."""
import json
import os
import pathlib

import pytest

import amp

PROBLEMS = pathlib.Path(os.environ["AMP_SOURCE_DIR"]) / "problems"


def test_a_plan_joins_start_and_goal_and_repeats_for_the_same_seed():
    problem = amp.load_problem(str(PROBLEMS / "walls.yaml"))
    assert problem.name == "Walls"
    assert problem.dimension == 3
    record, path = amp.plan(problem, planner="prm", seed=3)
    assert record["status"] == "solved"
    assert len(path) == record["path_states"]
    assert list(path[0]) == pytest.approx(problem.start)
    assert list(path[-1]) == pytest.approx(problem.goal)
    again, path2 = amp.plan(problem, planner="prm", seed=3)
    assert again["path_length"] == record["path_length"]
    assert [list(s) for s in path2] == [list(s) for s in path]


def test_params_and_limits_reach_the_planner():
    problem = amp.load_problem(str(PROBLEMS / "maze.yaml"))
    record, _ = amp.plan(problem, planner="prm", seed=1, params={"k": 5}, node_limit=50, time_limit=5.0)
    assert record["nodes"] <= 50


def test_errors_are_amp_errors_with_the_one_line_message():
    with pytest.raises(amp.Error, match="no_such_problem.yaml: no such file"):
        amp.load_problem("no_such_problem.yaml")
    problem = amp.load_problem(str(PROBLEMS / "walls.yaml"))
    with pytest.raises(amp.Error, match="unknown planner 'nope'"):
        amp.plan(problem, planner="nope")
    with pytest.raises(RuntimeError):  # amp.Error is a RuntimeError
        amp.plan(problem, params={"k": -3})


def test_navigation_methods_run_and_report():
    assert "sins" in amp.navigation_methods() and "prm" in amp.planners()
    arena = amp.load_problem(str(PROBLEMS / "sins-arena.yaml"))
    record, _ = amp.navigate(arena, "sins", seed=2, params={"worlds": 2, "step_limit": 100})
    assert record["status"] == "solved"
    assert record["extra"]["worlds"] == 2


def test_bench_writes_the_outputs(tmp_path):
    experiment = tmp_path / "tiny.yaml"
    experiment.write_text(
        "name: tiny\nseed: 1\nruns: 2\ntime_limit: 5\nproblems:\n  - %s\nplanners:\n  - prm\n"
        % (PROBLEMS / "walls.yaml")
    )
    result = amp.bench(str(experiment), out=str(tmp_path / "out"), threads=1)
    assert result["runs"] == 2
    assert (tmp_path / "out" / "runs.csv").exists()
    assert result["summary"]["experiment"]["name"] == "tiny"
    json.dumps(result["summary"])  # plain Python values all the way down


def test_an_arm_problem_plans_from_moveit_files_and_repeats():
    panda = PROBLEMS / "arms" / "panda"
    problem = amp.load_arm_problem(str(panda / "panda.urdf"), str(panda / "panda.srdf"),
                                   str(panda / "scenes" / "box" / "scene0001.yaml"),
                                   str(panda / "scenes" / "box" / "request0001.yaml"))
    assert problem.dimension == 7
    same = amp.load_problem(str(PROBLEMS / "panda-box.yaml"))
    assert same.start == pytest.approx(problem.start) and same.goal == pytest.approx(problem.goal)
    record, path = amp.plan(problem, planner="rrt-connect", seed=2, time_limit=30.0)
    assert record["status"] == "solved"
    assert list(path[0]) == pytest.approx(problem.start)
    assert list(path[-1]) == pytest.approx(problem.goal)
    again, path2 = amp.plan(problem, planner="rrt-connect", seed=2, time_limit=30.0)
    assert [list(s) for s in path2] == [list(s) for s in path]
    with pytest.raises(amp.Error, match="no-such-request.yaml"):
        amp.load_arm_problem(str(panda / "panda.urdf"), str(panda / "panda.srdf"),
                             str(panda / "scenes" / "box" / "scene0001.yaml"),
                             str(PROBLEMS / "arms" / "no-such-request.yaml"))


def test_load_problem_chooses_an_arms_collision_model(tmp_path, monkeypatch):
    monkeypatch.setenv("AMP_CACHE_DIR", str(tmp_path / "cache"))  # generated spheres: not the user's cache
    panda = pathlib.Path(os.environ["AMP_SOURCE_DIR"]).parent / "shared" / "mbm" / "panda"

    def arm_file(family, number):
        problem = tmp_path / ("%s-%s.yaml" % (family, number))
        problem.write_text("urdf: %s\nsrdf: %s\nscene: %s\nrequest: %s\n" % (
            panda / "panda.urdf", panda / "panda.srdf", panda / "problems" / family / ("scene%s.yaml" % number),
            panda / "problems" / family / ("request%s.yaml" % number)))
        return str(problem)

    box = arm_file("box", "0001")
    amp.load_problem(box)
    assert not (tmp_path / "cache").exists()  # meshes by default: no spheres made
    problem = amp.load_problem(box, collision="spheres")
    assert list((tmp_path / "cache").iterdir())  # the spheres were generated and cached
    record, path = amp.plan(problem, planner="rrt-connect", seed=1, time_limit=30.0)
    assert record["status"] == "solved"
    assert list(path[0]) == pytest.approx(problem.start) and list(path[-1]) == pytest.approx(problem.goal)
    # table_pick 0003's goal is free on the meshes but collides in the generated sphere model.
    goal_in_spheres = arm_file("table_pick", "0003")
    amp.load_problem(goal_in_spheres)
    record, path = amp.plan(amp.load_problem(goal_in_spheres, collision="spheres"), planner="rrt-connect")
    assert record["status"] == "unsolvable" and "sphere model" in record["message"] and len(path) == 0
    with pytest.raises(amp.Error, match="collision.*'cubes'"):
        amp.load_problem(box, collision="cubes")
    with pytest.raises(amp.Error, match="walls.yaml.*arm problem"):
        amp.load_problem(str(PROBLEMS / "walls.yaml"), collision="spheres")


# The keys of `amp navigate`'s record.json that are wall-clock times (all else is seeded).
NAVIGATE_TIMINGS = {"planning_time_median_s", "planning_time_s"}


def without_timings(value):
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k not in NAVIGATE_TIMINGS}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def test_navigate_with_runs_gives_what_amp_navigate_writes(tmp_path):
    import subprocess
    lab = PROBLEMS / "policy-lab.yaml"
    study = amp.navigate(amp.load_problem(str(lab)), "policy-search", seed=3, runs=2)
    out = tmp_path / "nav"
    subprocess.run([os.environ["AMP_CLI"], "navigate", str(lab), "--runs", "2", "--seed", "3", "-o", str(out)],
                   check=True, capture_output=True)
    written = json.loads((out / "record.json").read_text())
    # Table 2: both methods' rows, on the same seeds as the command's, the same figures.
    assert [row["method"] for row in study["table2"]] == ["policy-search", "dwa"]
    assert without_timings({k: study[k] for k in written}) == without_timings(written)
    assert study["table2"][0]["runs"] == 2 and study["table2"][0]["solved_runs"] <= 2
    # The phases of policy search (the paper's Table 1 and Figure 3), each a polyline in the map.
    names = [p["name"] for p in study["phases"]]
    assert len(names) == 4 and names[0].startswith("(a)") and names[-1].startswith("(d)")
    for phase in study["phases"]:
        assert len(phase["points"]) >= 2 and all(len(p) == 2 for p in phase["points"])
    assert set(study["speeds"]) == {"policy-search", "dwa"} and len(study["speeds"]["dwa"]) > 0
    assert len(study["trace"]) > 1


def test_navigate_with_runs_refuses_other_methods_and_unknown_params():
    lab = amp.load_problem(str(PROBLEMS / "policy-lab.yaml"))
    with pytest.raises(amp.Error, match="Table 2 compares"):
        amp.navigate(lab, "pgcs", runs=2)
    with pytest.raises(amp.Error, match="unknown parameter 'nope'"):
        amp.navigate(lab, "dwa", runs=1, params={"nope": 1})


def test_explore_and_sins_give_their_commands_records(tmp_path):
    import subprocess
    office = PROBLEMS / "office-map.yaml"
    record = amp.explore(amp.load_problem(str(office)), seed=2, params={"steps": 3000, "queries": 2})
    cli = subprocess.run([os.environ["AMP_CLI"], "explore", str(office), "--steps", "3000", "--queries", "2",
                          "--seed", "2", "--json"], check=True, capture_output=True, text=True)
    flat = json.loads(cli.stdout)
    timings = {"explore_time_s", "query_time_median_s"}
    assert {k: v for k, v in flat.items() if k not in timings} == \
        {k: record[k] for k in flat if k not in timings}
    assert record["settings"]["steps"] == 3000 and len(record["query_details"]) == 2

    sins = amp.sins("adaptive", seed=4, params={"worlds": 3})
    cli = subprocess.run([os.environ["AMP_CLI"], "sins", "--worlds", "3", "--seed", "4", "--json"],
                         check=True, capture_output=True, text=True)
    flat = json.loads(cli.stdout)
    assert {k: v for k, v in flat.items() if k != "time_per_world_ms_mean"} == \
        {k: sins[k] for k in flat if k != "time_per_world_ms_mean"}
    assert len(sins["world_outcomes"]) == 3
    with pytest.raises(amp.Error, match="unknown parameter 'nope'"):
        amp.sins(params={"nope": 1})
