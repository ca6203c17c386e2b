"""`--junit FILE` on `parksim sweep`, `report` and `run`, read by a real consumer (Debian's
python3-junitparser, which CI scripts use to read JUnit files) and checked against the
structure of the JUnit schema Jenkins validates (the xunit plugin's junit-10.xsd; GitLab reads
the same elements).

The schema is not vendored: its elements and attributes are restated below (JUNIT_SCHEMA) from
its published text. Set PARKSIM_JUNIT_XSD to a copy of junit-10.xsd to have xmllint validate
the files against it as well (docs/ci.md says where to get it).
"""

import json
import os
import pathlib
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET

import pytest

junitparser = pytest.importorskip("junitparser")

SOURCE_DIR = pathlib.Path(os.environ.get("PARKSIM_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))

# junit-10.xsd (jenkinsci/xunit-plugin), restated: element -> (required attributes, optional
# attributes, allowed children). The one extension parksim writes, <properties> inside
# <testcase> (as pytest, CTest and GoogleTest write it), is marked.
TESTCASE_EXTENSION = {"properties"}
RERUN = {"rerunFailure", "rerunError", "flakyFailure", "flakyError"}
JUNIT_SCHEMA = {
    "testsuites": (set(), {"name", "time", "tests", "failures", "errors"}, {"testsuite"}),
    "testsuite": ({"name", "tests", "failures", "errors"},
                  {"group", "time", "skipped", "timestamp", "hostname", "id", "package", "file",
                   "log", "url"},
                  {"testsuite", "properties", "testcase", "system-out", "system-err"}),
    "properties": (set(), set(), {"property"}),
    "property": ({"name", "value"}, set(), set()),
    "testcase": ({"name"}, {"time", "classname", "group"},
                 {"skipped", "error", "failure", "system-out", "system-err"} | RERUN),
    "failure": (set(), {"type", "message"}, set()),
    "error": (set(), {"type", "message"}, set()),
    "skipped": (set(), {"type", "message"}, set()),
    "system-out": (set(), set(), set()),
    "system-err": (set(), set(), set()),
}
SUREFIRE_TIME = re.compile(r"(([0-9]{0,3},)*[0-9]{3}|[0-9]{0,3})*(\.[0-9]*)?")


def check_schema(path):
    """Raises AssertionError where the file departs from junit-10.xsd (plus the extension)."""
    root = ET.parse(path).getroot()
    assert root.tag == "testsuites"

    def visit(element, parent):
        required, optional, children = JUNIT_SCHEMA[element.tag]
        attributes = set(element.attrib)
        assert required <= attributes, (element.tag, required - attributes)
        assert attributes <= required | optional, (element.tag, attributes - required - optional)
        if element.tag in ("testsuite", "testsuites") and "time" in element.attrib:
            assert SUREFIRE_TIME.fullmatch(element.attrib["time"]), element.attrib["time"]
        for child in element:
            allowed = children | (TESTCASE_EXTENSION if element.tag == "testcase" else set())
            assert child.tag in allowed, (element.tag, child.tag)
            visit(child, element)

    visit(root, None)
    xsd = os.environ.get("PARKSIM_JUNIT_XSD")
    if xsd and shutil.which("xmllint"):
        # The schema has no testcase properties: validate a copy without them.
        tree = ET.parse(path)
        for case in tree.iter("testcase"):
            for props in case.findall("properties"):
                case.remove(props)
        stripped = pathlib.Path(str(path) + ".stripped.xml")
        tree.write(stripped, encoding="utf-8", xml_declaration=True)
        p = subprocess.run(["xmllint", "--noout", "--schema", xsd, stripped],
                           capture_output=True, text=True)
        assert p.returncode == 0, p.stderr


def parksim(*args, ok=(0,)):
    exe = os.environ.get("PARKSIM_EXE")
    if not exe:
        pytest.skip("PARKSIM_EXE is not set (run through ctest)")
    p = subprocess.run([exe, *map(str, args)], capture_output=True, text=True, timeout=600)
    assert p.returncode in ok, f"exit {p.returncode}: {p.stderr}"
    return p


def rows_of(table):
    return [json.loads(line) for line in table.read_text(encoding="utf-8").splitlines()]


def cases_by_id(xml):
    """{episode_id: junitparser case} from the case names ("... id=<16 hex digits>")."""
    cases = {}
    for suite in junitparser.JUnitXml.fromfile(str(xml)):
        for case in suite:
            cases[re.search(r"id=([0-9a-f]{16})$", case.name).group(1)] = (suite, case)
    return cases


def failure_of(case):
    failures = [r for r in case.result if isinstance(r, junitparser.Failure)]
    return failures[0] if failures else None


@pytest.fixture(scope="module")
def sweep(tmp_path_factory):
    """A sweep with failures: a tight tracking bound (0.13 mm) that some of the unsmoothed tree
    planner's plans miss (0.14-0.17 mm; Hybrid A*'s 0.09 mm and one at 0.12 mm meet it), in a
    world whose name holds XML's markup characters and a non-ASCII letter (world files refuse
    control characters; XmlTextTest covers those)."""
    tmp = tmp_path_factory.mktemp("junit")
    world = (SOURCE_DIR / "worlds" / "head_in.yaml").read_text(encoding="utf-8")
    world = world.replace("name: head_in", 'name: "lot <A&B> \\"q\\" \u00e4"', 1)
    (tmp / "world.yaml").write_text(world, encoding="utf-8")
    (tmp / "spec.yaml").write_text(
        "format: parksim-sweep/1\nname: junit\nworlds: [world.yaml]\n"
        "planners: [rrt-goal-connect, hybrid-a-star]\nsmoothing: [false]\n"
        "seeds: {from: 1, to: 5}\n"
        "tolerance: {max_pos_err_m: 0.00013}\n", encoding="utf-8")
    out = tmp / "out"
    p = parksim("sweep", tmp / "spec.yaml", "--out", out, "--workers", "2", "--junit",
                tmp / "sweep.xml", ok=(0, 1))
    return tmp, out, p


def test_sweep_junit_counts_every_non_met_episode_as_a_failure_with_its_verdict_line(sweep):
    tmp, out, p = sweep
    rows = rows_of(out / "results.jsonl")
    failed = [r for r in rows if not r["met_tolerance"]]
    assert failed and len(failed) < len(rows), "the spec must give both outcomes"
    assert p.returncode == 1
    xml = junitparser.JUnitXml.fromfile(str(tmp / "sweep.xml"))
    xml.update_statistics()
    assert xml.tests == len(rows)
    assert xml.failures == len(failed)
    assert xml.errors == 0
    cases = cases_by_id(tmp / "sweep.xml")
    assert set(cases) == {r["episode_id"] for r in rows}
    for row in rows:
        suite, case = cases[row["episode_id"]]
        failure = failure_of(case)
        if row["met_tolerance"]:
            assert failure is None
        else:
            assert failure is not None and failure.message == row["failure"]
            assert failure.type == row["status"]
        assert case.time >= 0.0


def test_sweep_junit_groups_by_world_planner_and_realism_with_parameters_as_properties(sweep):
    tmp, out, _ = sweep
    names = sorted(s.name for s in junitparser.JUnitXml.fromfile(str(tmp / "sweep.xml")))
    world = "lot <A&B> \"q\" \u00e4"
    assert names == [f"{world} / hybrid-a-star / world", f"{world} / rrt-goal-connect / world"]
    root = ET.parse(tmp / "sweep.xml").getroot()
    case = root.find("testsuite/testcase")
    props = {p.get("name"): p.get("value") for p in case.find("properties")}
    for key in ("episode_id", "world", "world_file", "planner", "steering", "smooth", "seed",
                "max_iterations", "tracking", "timing", "realism", "noise_seed", "start_dx_m",
                "goal_dyaw_deg", "status"):
        assert key in props, key
    assert props["world"] == world


def test_junit_files_follow_the_schema_jenkins_and_gitlab_read(sweep):
    tmp, out, _ = sweep
    check_schema(tmp / "sweep.xml")
    raw = (tmp / "sweep.xml").read_bytes()
    raw.decode("utf-8")  # valid UTF-8 throughout
    assert b"\x1b" not in raw
    if shutil.which("xmllint"):
        p = subprocess.run(["xmllint", "--noout", tmp / "sweep.xml"], capture_output=True)
        assert p.returncode == 0, p.stderr


def test_report_junit_is_the_sweeps(sweep):
    tmp, out, _ = sweep
    parksim("report", out, "--out", tmp / "report", "--junit", tmp / "report.xml")
    check_schema(tmp / "report.xml")
    a, b = cases_by_id(tmp / "sweep.xml"), cases_by_id(tmp / "report.xml")
    assert a.keys() == b.keys()
    for key in a:
        fa, fb = failure_of(a[key][1]), failure_of(b[key][1])
        assert (fa is None) == (fb is None)
        if fa is not None:
            assert fa.message == fb.message


def test_run_junit_has_one_case_per_realisation(tmp_path):
    parksim("run", SOURCE_DIR / "worlds" / "head_in.yaml", "--realism", "lab",
            "--realisations", "3", "--noise-seed", "7", "--max-tracking-error-mm", "1.0",
            "--out", tmp_path / "run", "--junit", tmp_path / "run.xml", ok=(0, 4))
    check_schema(tmp_path / "run.xml")
    xml = junitparser.JUnitXml.fromfile(str(tmp_path / "run.xml"))
    suites = list(xml)
    # Named as a sweep names the same episodes: one writer for both.
    assert len(suites) == 1 and suites[0].name == "head_in / time-a-star+smooth / lab"
    cases = list(suites[0])
    assert [c.name for c in cases] == ["seed=1 noise_seed=7", "seed=1 noise_seed=8",
                                       "seed=1 noise_seed=9"]
    metrics = json.loads((tmp_path / "run" / "metrics.json").read_text())
    statuses = [metrics[f"realisation.{i}.status"] for i in range(3)]
    for case, status in zip(cases, statuses):
        failure = failure_of(case)
        assert (failure is None) == (status == "met")
        if failure is not None:
            assert failure.type == status and failure.message


def test_a_junit_path_in_a_missing_folder_is_refused_before_anything_runs(tmp_path):
    p = parksim("run", SOURCE_DIR / "worlds" / "head_in.yaml", "--out", tmp_path / "out",
                "--junit", tmp_path / "no" / "such" / "r.xml", ok=(2,))
    assert "does not exist" in p.stderr
    assert not (tmp_path / "out").exists()
