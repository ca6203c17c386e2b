"""parksim's pages in a real browser (parksim/pages/, docs/pages.md): Debian's headless Chromium
driven through chromedriver (scripts/page_browser.py), one session for every test here.

Each kind of page is made by the command a user runs (`run`, `sweep` + `report`, `compare
--html`), opened from file:// and must draw itself (data-ready) with no console error and no
request outside its folder. Then the pages are used: the replay at a chosen time puts the robot
where the record says (its state and its pixels); sorting and filtering the sweep's table
change what it shows, and the per-axis summaries agree with the table; every failed episode a
held-out sweep kept is reachable from its table by a click and replays; the comparison links a
regressed group's paired episodes."""

import json
import math
import os
import pathlib
import subprocess
import sys
import time
import urllib.parse

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("PARKSIM_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
EXE = os.environ.get("PARKSIM_EXE", str(SOURCE_DIR / "build" / "app" / "parksim"))
sys.path.insert(0, str(SOURCE_DIR / "scripts"))
from page_browser import PageBrowser  # noqa: E402

from selenium.webdriver import ActionChains  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402


def parksim(*args, ok=(0,)):
    proc = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True)
    assert proc.returncode in ok, (args, proc.returncode, proc.stderr)
    return proc


def spec(path, text):
    path.write_text(text.replace("WORLDS", str(SOURCE_DIR / "worlds")))
    return path


@pytest.fixture(scope="session")
def browser():
    with PageBrowser() as b:
        yield b


@pytest.fixture(scope="session")
def out(tmp_path_factory):
    """Every page kind, made by the commands a user runs."""
    root = tmp_path_factory.mktemp("pages")
    parksim("run", SOURCE_DIR / "worlds/head_in.yaml", "--out", root / "run")
    parksim("run", SOURCE_DIR / "worlds/head_in.yaml", "--realism", "lab", "--out", root / "lab")
    parksim("sweep", SOURCE_DIR / "worlds/sweeps/study.yaml", "--out", root / "study", "-q",
            ok=(1,))
    parksim("report", root / "study", "--junit", root / "study.xml")
    # Held out: worlds, realisms and open loops the pages were not written against, with
    # contacts and missed goals among them; failures keep their files (NumPy records).
    spec(root / "held.yaml", """format: parksim-sweep/1
name: held-out
worlds: [WORLDS/tight_parallel.yaml, WORLDS/clutter.yaml]
tracking: [closed, open]
realism: [ideal, odometry]
record: {executed_csv: failures, executed_rate_hz: 40}
""")
    parksim("sweep", root / "held.yaml", "--out", root / "held", "-q", ok=(1,))
    parksim("report", root / "held")
    # A comparison with a regression: the same lab episodes judged by a tighter tolerance.
    base = """format: parksim-sweep/1
name: lab
worlds: [WORLDS/head_in.yaml]
realism: lab
noise_seeds: {from: 1, to: 8}
record: {executed_csv: all, executed_rate_hz: 20}
"""
    spec(root / "base.yaml", base)
    spec(root / "cand.yaml", base + "tolerance: {max_pos_err_m: 0.0011}\n")
    parksim("sweep", root / "base.yaml", "--out", root / "base", "-q")
    parksim("sweep", root / "cand.yaml", "--out", root / "cand", "-q", ok=(1,))
    (root / "ci").mkdir()
    parksim("compare", root / "base", root / "cand", "--html", root / "ci" / "compare.html", ok=(4,))
    return root


def rows_of(table):
    return [json.loads(line) for line in (table / "results.jsonl").read_text().splitlines()]


def open_clean(browser, page, folder):
    """Opens a page; it must be drawn with no console error and nothing fetched from outside
    `folder` (the page's own folder)."""
    seconds = browser.open(page)
    assert browser.console_errors() == []
    assert browser.requests_outside(folder) == []
    return seconds


def record_of(folder):
    """The episode's record as written: executed.csv or executed.npz, columns by name."""
    csv = folder / "executed.csv"
    if csv.exists():
        data = np.genfromtxt(csv, delimiter=",", names=True)
        return {name: data[name] for name in data.dtype.names}
    with np.load(folder / "executed.npz") as npz:
        return {name: npz[name] for name in npz.files}


def check_replay_at(browser, record, t):
    """Moves the scrubber to the row of time t as a user would (an input event on it) and checks
    the robot is drawn where that row says: the replay's state and the canvas's pixels."""
    index = int(np.searchsorted(record["t"], t, side="right") - 1)
    browser.js("const s = document.getElementById('scrubber'); s.value = arguments[0];"
               "s.dispatchEvent(new Event('input'));", index)
    state = browser.js("return parksimReplay.state()")
    assert state["index"] == index
    for key in ("t", "x", "y", "theta"):
        assert state[key] == record[key][index], key
    assert browser.js("return parksimReplay.indexAt(arguments[0])", t) == index
    # A point inside the body, clear of the heading marker and the wheels, has the robot's colour.
    pixel = browser.js("""
        const r = parksimReplay, s = r.state(), robot = r.data.robot;
        const u = robot.front_overhang_m - 0.85 * robot.length_m, v = 0.3 * robot.width_m;
        const [px, py] = r.toScreen(s.x + Math.cos(s.theta) * u - Math.sin(s.theta) * v,
                                    s.y + Math.sin(s.theta) * u + Math.cos(s.theta) * v);
        const d = r.view.dpr;
        const p = r.canvas.getContext('2d').getImageData(Math.round(px * d), Math.round(py * d), 1, 1).data;
        return [p[0], p[1], p[2], r.style.robot];""")
    want = [int(pixel[3][i:i + 2], 16) for i in (1, 3, 5)]
    assert max(abs(a - b) for a, b in zip(pixel[:3], want)) <= 2, (pixel, want)
    return index


def test_episode_page_replays_the_record(browser, out):
    run = out / "run"
    open_clean(browser, run / "report.html", run)
    assert browser.js("return document.getElementById('verdict').textContent") == "met its tolerance"
    record = record_of(run)
    assert browser.js("return parksimReplay.rows") == len(record["t"])
    # One length unit, mm, as on the sweep's table: metrics.json's metres shown under "_mm".
    metrics = json.loads((run / "metrics.json").read_text())
    shown = dict(browser.js("return [...document.querySelectorAll('.metrics tr')]"
                            ".map(tr => [tr.children[0].textContent, tr.children[1].textContent])"))
    assert not [k for k in shown if k.endswith("_m")]
    assert float(shown["max_pos_err_mm"]) == pytest.approx(1e3 * metrics["max_pos_err_m"], rel=1e-5)
    assert float(shown["final_x_mm"]) == pytest.approx(1e3 * metrics["final_x_m"], rel=1e-5)
    # Three plots over time: position error with its tolerance, heading error, wheel speeds.
    assert browser.js("return document.querySelectorAll('.plots .uplot').length") == 3
    for t in (0.0, 3.3, 6.0, 11.75, 1e9):
        check_replay_at(browser, record, t)
    # A legend says what each colour of the replay means, in the colours it draws with.
    legend = browser.js("return [...document.querySelectorAll('#replay-legend li')]"
                        ".map(li => [li.dataset.key, li.dataset.color, li.textContent])")
    style = browser.js("return parksimReplay.style")
    assert [k for k, _, _ in legend] == ["planned", "executed", "robot", "reference", "start",
                                         "goal", "contact"]
    assert all(color == style[key] and text for key, color, text in legend)
    # A scale bar in mm: a 1, 2 or 5 x 10^k length at most 120 px wide, drawn where it says,
    # and shorter after zooming in.
    def scale_bar():
        bar, scale = browser.js("const r = parksimReplay; return [r.scaleBar(), r.view.scale]")
        assert bar["px"] == pytest.approx(bar["mm"] / 1000 * scale)
        assert 48 <= bar["px"] <= 120
        assert bar["mm"] / 10 ** math.floor(math.log10(bar["mm"]) + 1e-9) in (1, 2, 5)
        assert bar["label"] == "%g mm" % bar["mm"]
        dark = browser.js("""
            const r = parksimReplay, b = r.scaleBar(), d = r.view.dpr;
            const p = r.canvas.getContext('2d').getImageData(Math.round((12 + b.px / 2) * d),
                Math.round((r.view.h - 14) * d), 1, 1).data;
            return p[0] + p[1] + p[2] < 200;""")
        assert dark
        return bar["mm"]
    before = scale_bar()
    browser.js("parksimReplay.view.scale *= 4; parksimReplay.view.dirty = true; parksimReplay.draw()")
    assert scale_bar() < before
    browser.js("parksimReplay.fit()")
    # A click on a plot moves the replay to the time under the pointer.
    plot = browser.driver.find_elements(By.CSS_SELECTOR, ".plots .u-over")[0]
    browser.driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", plot)
    ActionChains(browser.driver).move_to_element_with_offset(plot, 0, 0).click().perform()
    t = browser.js("return parksimReplay.state().t")
    duration = record["t"][-1]
    assert 0.3 * duration < t < 0.7 * duration
    # Play runs the replay forward.
    browser.js("document.getElementById('speed').value = '20';"
               "document.getElementById('scrubber').value = 0;"
               "document.getElementById('scrubber').dispatchEvent(new Event('input'));"
               "document.getElementById('play').click()")
    time.sleep(0.5)
    assert browser.js("return parksimReplay.index") > 0
    browser.js("document.getElementById('play').click()")
    assert browser.console_errors() == []


def test_episode_page_under_a_realism_plots_the_estimate(browser, out):
    lab = out / "lab"
    open_clean(browser, lab / "report.html", lab)
    record = record_of(lab)
    assert browser.js("return document.querySelectorAll('.plots .uplot').length") == 4
    assert "estimate" in browser.js("return [...document.querySelectorAll('#replay-legend li')].map(li => li.dataset.key)")
    titles = browser.js("return [...document.querySelectorAll('.u-title')].map(e => e.textContent)")
    assert any("Estimate against the truth" in t for t in titles)
    # Every y axis is labelled with its one unit; the estimate's plot has one axis per unit.
    labels = browser.js("return parksimPlots.map(u => u.axes.slice(1).map(a => a.label))")
    assert labels == [["error (mm)"], ["error (deg)"], ["speed (rad/s)"],
                      ["position error (mm)", "heading error (deg)"]]
    # The hover legend shows significant digits with the unit, not 0.00029 mm rounded to "0";
    # the position error's legend shows the record's value, not the log plot's floor.
    i = int(np.argmax(record["pos_err"]))
    legend = browser.js("const u = parksimPlots[0], e = parksimPlots[3];"
                        "return [u.series[1].value(u, 0.00029, 1, null), u.series[1].value(u, 1e-4, 1, arguments[0]),"
                        " e.series[2].value(e, 0.0123, 2, null)]", i)
    assert legend[0] == "0.00029 mm"
    assert legend[1].endswith(" mm")
    assert float(legend[1][:-3]) == pytest.approx(1e3 * record["pos_err"][i], rel=5e-3)
    assert legend[2] == "0.0123 deg"
    state_index = check_replay_at(browser, record, 4.0)
    estimate = browser.js("const r = parksimReplay, i = r.index;"
                          "return [r.track.xe[i], r.track.ye[i], r.track.the[i]]")
    assert estimate == [record["x_est"][state_index], record["y_est"][state_index],
                        record["theta_est"][state_index]]


def test_sweep_page_holds_every_episode(browser, out):
    report = out / "study" / "report"
    seconds = open_clean(browser, report / "index.html", report)
    assert seconds < 10
    rows = rows_of(out / "study")
    assert len(rows) == 120
    assert browser.js("return document.body.dataset.rows") == "120"
    assert browser.js("return document.body.dataset.shown") == "120"
    # Every status is offered, with its count (zero for those no episode has).
    chips = browser.js("return [...document.querySelectorAll('#status-filter .chip')]"
                       ".map(c => [c.dataset.status, Number(c.querySelector('.count').textContent)])")
    statuses = [c[0] for c in chips]
    for status in ("met", "plan_failed", "plan_invalid", "planner_error", "controller_error",
                   "contact", "goal_missed", "tolerance_missed"):
        assert status in statuses
    for status, count in chips:
        assert count == sum(r["status"] == status for r in rows), status
    # The JUnit report links its suites to the page and kept episodes to theirs.
    xml = (out / "study.xml").read_text()
    assert 'name="html_report" value="study/report/index.html"' in xml
    kept = [r["episode_id"] for r in rows if (out / "study/episodes" / r["episode_id"] / "report.html").exists()]
    assert kept and all('value="study/episodes/%s/report.html"' % k in xml for k in kept)


def column_field(browser, name):
    return browser.js("return parksimTable.getColumns().find(c => c.getDefinition().title === arguments[0]).getField()", name)


def shown_values(browser, field):
    return browser.js("return parksimTable.getRows('active').map(r => r.getData()[arguments[0]])", field)


def test_sorting_and_filtering_change_what_is_shown(browser, out):
    report = out / "study" / "report"
    open_clean(browser, report / "index.html", report)
    rows = rows_of(out / "study")
    # Lengths in mm, as on the episode pages: the column max_pos_err_m is titled "_mm".
    errors = sorted(1e3 * r["max_pos_err_m"] for r in rows if "max_pos_err_m" in r)
    field = column_field(browser, "max_pos_err_mm")

    def click_header():
        title = browser.driver.find_element(
            By.CSS_SELECTOR, '.tabulator-col[tabulator-field="%s"] .tabulator-col-title' % field)
        browser.driver.execute_script("arguments[0].scrollIntoView({block: 'center', inline: 'center'})", title)
        ActionChains(browser.driver).move_to_element(title).click().perform()

    def first_shown():
        return browser.driver.find_element(
            By.CSS_SELECTOR, '.tabulator-row:first-child .tabulator-cell[tabulator-field="%s"]' % field).text

    click_header()
    assert float(first_shown()) == pytest.approx(errors[0], rel=1e-3)
    click_header()
    assert float(first_shown()) == pytest.approx(errors[-1], rel=1e-3)
    # A number filter under the header: only the episodes above 0.1 mm stay.
    box = browser.driver.find_element(By.CSS_SELECTOR, '.tabulator-col[tabulator-field="%s"] input' % field)
    box.send_keys(">0.1")
    expected = sum(1 for e in errors if e > 0.1)
    wait_for(browser, "return document.body.dataset.shown", str(expected))
    assert all(v > 0.1 for v in shown_values(browser, field))
    # The per-axis summaries follow the filter.
    shown_total = sum(int(td) for td in browser.js(
        "return [...document.querySelectorAll('[data-axis=\"world\"] table.summary tbody tr td:nth-child(2)')].map(e => e.textContent)"))
    assert shown_total == expected
    box.clear()
    box.send_keys("\b")
    wait_for(browser, "return document.body.dataset.shown", "120")
    # Status chips: hiding "met" leaves the failures.
    browser.driver.find_element(By.CSS_SELECTOR, '#status-filter .chip[data-status="met"]').click()
    failed = [r for r in rows if r["status"] != "met"]
    wait_for(browser, "return document.body.dataset.shown", str(len(failed)))
    assert sorted(shown_values(browser, column_field(browser, "episode_id"))) == sorted(r["episode_id"] for r in failed)
    browser.driver.find_element(By.CSS_SELECTOR, '#status-filter .chip[data-status="met"]').click()
    wait_for(browser, "return document.body.dataset.shown", "120")
    # A column not shown at first is one click away, and sorts.
    assert browser.js("return parksimTable.getColumns().some(c => c.getDefinition().title === 'plan_iterations')") is False
    browser.driver.find_element(By.CSS_SELECTOR, ".chooser summary").click()
    browser.driver.find_element(By.XPATH, "//details[@class='chooser']//label[normalize-space()='plan_iterations']/input").click()
    browser.driver.find_element(By.CSS_SELECTOR, ".chooser summary").click()
    field = column_field(browser, "plan_iterations")
    click_header()
    assert float(first_shown()) == min(r["plan_iterations"] for r in rows)


def test_few_valued_numbers_filter_by_comparison_and_a_third_click_restores_failures_first(browser, out):
    # Eight episodes: each number column has at most eight values, which were offered as a
    # list of raw floats, so ">0.0001" matched nothing (issue 39, point 6).
    report = out / "held" / "report"
    open_clean(browser, report / "index.html", report)
    rows = rows_of(out / "held")
    statuses = browser.js("return [...document.querySelectorAll('#status-filter .chip')].map(c => c.dataset.status)")
    rank = {s: (len(statuses) + 1 if s == "met" else k + 1) for k, s in enumerate(statuses)}
    failures_first = sorted(range(len(rows)), key=lambda i: (rank[rows[i]["status"]], i))
    assert failures_first != list(range(len(rows)))  # the file's order is not the failures-first one
    order = "return parksimTable.getRows('active').map(r => r.getData()._i)"
    assert browser.js(order) == failures_first
    field = column_field(browser, "max_pos_err_mm")
    title = browser.driver.find_element(
        By.CSS_SELECTOR, '.tabulator-col[tabulator-field="%s"] .tabulator-col-title' % field)
    browser.driver.execute_script("arguments[0].scrollIntoView({block: 'center', inline: 'center'})", title)
    for _ in range(3):
        ActionChains(browser.driver).move_to_element(title).click().perform()
    assert browser.js(order) == failures_first
    errors = [1e3 * r["max_pos_err_m"] for r in rows if "max_pos_err_m" in r]  # mm
    for query, keep in ((">0.1", lambda e: e > 0.1), ("<=10", lambda e: e <= 10),
                        ("0..1", lambda e: 0 <= e <= 1)):
        box = browser.driver.find_element(By.CSS_SELECTOR, '.tabulator-col[tabulator-field="%s"] input' % field)
        assert box.get_attribute("readonly") is None
        box.send_keys(Keys.CONTROL, "a")
        box.send_keys(query)
        expected = sum(1 for e in errors if keep(e))
        wait_for(browser, "return document.body.dataset.shown", str(expected))
    assert 0 < sum(1 for e in errors if e > 0.1) < len(rows)


def wait_for(browser, script, value, tries=200):
    for _ in range(tries):
        got = browser.js(script)
        if got == value:
            return
        time.sleep(0.02)
    raise AssertionError("%s: %r, wanted %r" % (script, got, value))


def wilson(k, n, z=1.959963984540054):
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z / (1 + z * z / n) * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    return max(0.0, centre - half), min(1.0, centre + half)


def test_axis_summaries_agree_with_the_table(browser, out):
    report = out / "study" / "report"
    open_clean(browser, report / "index.html", report)
    rows = rows_of(out / "study")
    cells = browser.js("return [...document.querySelectorAll('[data-axis=\"planner\"] table.summary tbody tr')]"
                       ".map(tr => [...tr.children].map(td => td.textContent))")
    planners = sorted({r["planner"] for r in rows})
    assert [c[0] for c in cells] == planners
    # world_file groups the episodes as world does: no second summary; the seed is a
    # replicate, not an axis (issue 39, point 6).
    axes = browser.js("return [...document.querySelectorAll('#axes .axis')].map(a => a.dataset.axis)")
    assert axes == ["world", "planner"]
    for planner, cell in zip(planners, cells):
        group = [r for r in rows if r["planner"] == planner]
        met = sum(r["met_tolerance"] for r in group)
        low, high = wilson(met, len(group))
        assert cell[1] == str(len(group)) and cell[2] == str(met)
        assert cell[3] == "%.1f %% (%.1f .. %.1f %%)" % (100 * met / len(group), 100 * low, 100 * high)
        errors = np.array([r["max_pos_err_m"] for r in group if "max_pos_err_m" in r])
        assert cell[4] == "%.3f / %.3f / %.3f mm" % (1e3 * np.quantile(errors, 0.5),
                                                    1e3 * np.quantile(errors, 0.95), 1e3 * errors.max())


def test_max_error_histograms_per_group(browser, out):
    report = out / "study" / "report"
    open_clean(browser, report / "index.html", report)
    rows = rows_of(out / "study")
    hist = browser.js("return parksimHistograms.planner")
    encoding = browser.js("return parksim.data().table.columns.find(c => c.name === 'max_pos_err_m').encoding")
    # The page's values: float32 when packed as numbers (ColumnCodec), shown in mm.
    def mm(x):
        return 1e3 * (float(np.float32(x)) if encoding == "number" else x)
    errors = [mm(r["max_pos_err_m"]) for r in rows if "max_pos_err_m" in r]
    edges = np.array(hist["edges"])
    # 12 bins spaced evenly in log10 from the smallest error to the largest.
    assert len(edges) == 13
    assert edges[0] == min(errors) and edges[-1] == max(errors)
    steps = np.diff(np.log10(edges))
    assert np.allclose(steps, steps[0], rtol=1e-9)
    # Each planner's counts are NumPy's histogram of its errors over those edges.
    planners = sorted({r["planner"] for r in rows})
    assert sorted(g["label"] for g in hist["groups"]) == planners
    for g in hist["groups"]:
        mine = [mm(r["max_pos_err_m"]) for r in rows if r["planner"] == g["label"] and "max_pos_err_m" in r]
        assert g["counts"] == np.histogram(mine, edges)[0].tolist(), g["label"]
    titles = browser.js("return [...document.querySelectorAll('[data-axis=\"planner\"] .u-title')].map(e => e.textContent)")
    assert any(t.startswith("Max tracking error per planner") for t in titles), titles


def test_failed_kept_episodes_of_a_held_out_sweep_are_reachable_and_replay(browser, out):
    held = out / "held"
    report = held / "report"
    open_clean(browser, report / "index.html", report)
    failed = [r for r in rows_of(held) if not r["met_tolerance"]]
    assert len(failed) >= 4
    assert {"contact", "goal_missed"} <= {r["status"] for r in failed}
    # Each failure is found in the table by its id, with a link to its page.
    id_field = column_field(browser, "episode_id")
    box = browser.driver.find_element(By.CSS_SELECTOR, '.tabulator-col[tabulator-field="%s"] input' % id_field)
    for row in failed:
        box.send_keys(Keys.CONTROL, "a")
        box.send_keys(row["episode_id"])
        wait_for(browser, "const a = document.querySelectorAll('.tabulator-row a');"
                 "return document.body.dataset.shown + ' ' + (a.length ? a[0].textContent : '')",
                 "1 " + row["episode_id"])
        link = browser.driver.find_element(By.CSS_SELECTOR, '.tabulator-row a')
        page = held / "episodes" / row["episode_id"] / "report.html"
        assert page.exists()
        assert link.get_attribute("href") == page.resolve().as_uri()
    # One is opened by a click, as a reader would; every one replays.
    link.click()
    browser.wait_ready(page)
    for row in failed:
        folder = held / "episodes" / row["episode_id"]
        open_clean(browser, folder / "report.html", folder)
        verdict = browser.js("return document.getElementById('verdict').textContent")
        assert verdict == row["failure"]
        record = record_of(folder)
        # At the first row at or after the first contact (or at the end): the robot where the
        # record says, and the contact drawn.
        first_contact = row.get("first_contact_t_s", -1)
        at = record["t"][-1]
        if first_contact >= 0:
            at = record["t"][np.searchsorted(record["t"], first_contact, side="left")]
        check_replay_at(browser, record, at)
        if first_contact >= 0:
            drawn = browser.js("return parksimReplay.contacts.filter(c => c.t_s <= parksimReplay.state().t).length")
            assert drawn >= 1


def test_comparison_page_links_the_regressed_groups_episodes(browser, out):
    page = out / "ci" / "compare.html"
    open_clean(browser, page, out / "ci")
    assert browser.js("return document.getElementById('verdict').textContent") == "1 of 5 tests found a regression"
    # What differs between the two configurations: the candidate's spec adds a tolerance; the
    # rows' parameters, build and worlds are the same.
    differences = browser.js("return [...document.querySelectorAll('#differences tbody tr')]"
                             ".map(tr => [...tr.children].map(td => td.textContent))")
    assert differences == [["spec", "", "tolerance: {max_pos_err_m: 0.0011}"]]
    groups = browser.js("return [...document.querySelectorAll('#pairs .pairs')].map(g => g.dataset.group)")
    assert groups[0].startswith("head_in /")
    assert browser.js("return document.body.dataset.rows") == "5"
    links = browser.js("return [...document.querySelectorAll('#pairs a')].map(a => a.getAttribute('href'))")
    assert len(links) == 16
    cand = [r for r in rows_of(out / "cand") if not r["met_tolerance"]]
    # The worst changes first: the episodes that now fail come before those that still pass.
    first = browser.js("return [...document.querySelectorAll('#pairs tbody tr td:first-child')].map(e => e.textContent)")
    assert set(first[:len(cand)]) == {r["episode_id"] for r in cand}
    link = browser.driver.find_element(By.CSS_SELECTOR, '#pairs a[href*="cand/"]')
    href = urllib.parse.urlparse(link.get_attribute("href"))  # resolved: file:///...
    link.click()
    browser.wait_ready(pathlib.Path(urllib.parse.unquote(href.path)))
    assert browser.js("return document.getElementById('verdict').textContent") in (
        {r["failure"] for r in cand} | {"met its tolerance"})
    assert browser.console_errors() == []
