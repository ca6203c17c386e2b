"""Names from input files are text on every page (issue 39, point 1), in Debian's headless
Chromium (scripts/page_browser.py).

Worlds, obstacles, parked robots, world files, sweeps and sweep folders are named with markup,
quotes, `</script>` and `javascript:`. An episode page (driven, and one whose plan is refused
naming an obstacle), a sweep's page and a comparison's page made from them by the commands a
user runs must each: open no dialog, log no console error (no Content-Security-Policy
violation), hold no element a name could have made, link only to files, and show every name
as the text it is where the page shows it (titles, table cells, column titles, filter lists,
group headers, the verdict). Then, on every page, markup put in by script (as a name shown as
HTML would be) must not run: the page's policy refuses inline handlers and scripts."""

import csv
import json
import os
import pathlib
import subprocess
import sys
import urllib.parse

import pytest
import yaml

SOURCE_DIR = pathlib.Path(os.environ.get("PARKSIM_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
EXE = os.environ.get("PARKSIM_EXE", str(SOURCE_DIR / "build" / "app" / "parksim"))
sys.path.insert(0, str(SOURCE_DIR / "scripts"))
from page_browser import PageBrowser  # noqa: E402

# A '/' too: `report` names a file after the world (issue 39, point 6).
WORLD_A = "<img src=x onerror=alert(11)> \"q\" 's javascript:alert(12) ../lots/a"
WORLD_B = "<svg onload=alert(13)> &amp; \u00e9"
WALL = "\"><img src=x onerror=alert(21)></script><script>alert(22)</script>"
ISLAND = "<img src=x onerror=alert(23)> </script>"
PARKED_A = "javascript:alert(31)"
PARKED_B = "<img src=x onerror=alert(32)> '</script>"
PARKED_C = "<svg onload=alert(33)>"
FILE_A = "<img src=x onerror=alert(14)>.yaml"
FILE_B = "world \"b\" 's.yaml"
SWEEP = "sweep <img src=x onerror=alert(41)>"
CANDIDATE = "cand <svg onload=alert(42)>"
BASE_DIR = "javascript:alert(15)"


def parksim(*args, ok=(0,)):
    proc = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True)
    assert proc.returncode in ok, (args, proc.returncode, proc.stderr)
    return proc


def world(name, renames):
    """worlds/head_in.yaml with its name and some of its obstacles' and parked robots' names
    replaced (old name -> new)."""
    data = yaml.safe_load((SOURCE_DIR / "worlds/head_in.yaml").read_text())
    data["name"] = name
    for item in data["obstacles"] + data["parked_robots"]:
        item["name"] = renames.get(item["name"], item["name"])
    return yaml.safe_dump(data, allow_unicode=True)


@pytest.fixture(scope="session")
def out(tmp_path_factory):
    root = tmp_path_factory.mktemp("hostile")
    (root / FILE_A).write_text(world(WORLD_A, {"wall_2": WALL, "island_7": ISLAND,
                                               "robot_5": PARKED_A, "robot_6": PARKED_B}))
    (root / FILE_B).write_text(world(WORLD_B, {"wall_1": WALL, "robot_3": PARKED_C}))
    # An episode driven, and one refused before driving: its plan crosses the island, moved
    # onto the plan's middle, and the verdict names it.
    parksim("run", root / FILE_A, "--out", root / "run")
    with open(root / "run" / "trajectory.csv") as f:
        rows = list(csv.DictReader(f))
    middle = rows[len(rows) // 2]
    parksim("run", root / FILE_A, "--plan", root / "run" / "trajectory.csv",
            "--set", "obstacles[2].center=[%s,%s]" % (middle["x"], middle["y"]),
            "--set", "obstacles[2].size=[0.02,0.02]", "--out", root / "invalid", ok=(5,))
    spec = {"format": "parksim-sweep/1", "worlds": [FILE_A, FILE_B], "planners": ["rrt"],
            "seeds": {"from": 1, "to": 2}, "tracking": ["closed", "open"],
            "record": {"executed_csv": "all", "executed_rate_hz": 20}}
    (root / "base.yaml").write_text(json.dumps(dict(spec, name=SWEEP)))
    (root / "cand.yaml").write_text(json.dumps(dict(spec, name=CANDIDATE,
                                                    tolerance={"max_pos_err_m": 0.0001})))
    parksim("sweep", root / "base.yaml", "--out", root / BASE_DIR, "-q", ok=(0, 1))
    parksim("report", root / BASE_DIR)
    parksim("sweep", root / "cand.yaml", "--out", root / "cand", "-q", ok=(1,))
    # Beside the sweeps: its links begin with the baseline folder's name, "javascript:...".
    parksim("compare", root / BASE_DIR, root / "cand", "--html", root / "compare.html", ok=(0, 4))
    return root


@pytest.fixture(scope="session")
def browser():
    with PageBrowser() as b:
        yield b


def texts(browser, selector):
    return browser.js("return [...document.querySelectorAll(arguments[0])].map(e => e.textContent)",
                      selector)


def open_page(browser, page):
    """Opens a page made from hostile names: drawn, no dialog, no console error, no element a
    name could have made, every link to a file."""
    browser.open(page)
    assert browser.dialogs() == []
    assert browser.console_errors() == []
    assert browser.js("return document.querySelectorAll("
                      "'img, svg, iframe, object, embed, [onerror], [onload]').length") == 0
    assert browser.js("return [...document.links].filter(a => a.protocol !== 'file:')"
                      ".map(a => a.getAttribute('href'))") == []


def markup_does_not_run(browser):
    """Markup put into the page by script, as a name shown as HTML would be, runs nothing: the
    policy refuses the inline handler, the inline script and the javascript: link, each a
    violation the page is told of."""
    result = browser.driver.execute_async_script("""
        const done = arguments[arguments.length - 1];
        const seen = [];
        document.addEventListener('securitypolicyviolation', (e) => seen.push(e.violatedDirective));
        window.parksimInjected = [];
        const box = document.createElement('div');
        box.innerHTML = '<img src="data:," onerror="parksimInjected.push(1)">' +
          '<a id="parksim-injected" href="javascript:parksimInjected.push(3)">x</a>';
        document.body.append(box);
        const s = document.createElement('script');
        s.textContent = 'parksimInjected.push(2)';
        document.body.append(s);
        document.getElementById('parksim-injected').click();
        setTimeout(() => done([window.parksimInjected, seen]), 500);""")
    ran, violations = result
    assert ran == []
    assert len(violations) >= 3 and all(v.startswith("script-src") for v in violations), violations
    assert browser.dialogs() == []


def test_episode_pages_show_names_as_text(browser, out):
    for folder in ("run", "invalid"):
        open_page(browser, out / folder / "report.html")
        assert browser.js("return document.querySelector('h1 span').textContent") == WORLD_A
        assert WORLD_A in browser.js("return document.title")
        facts = texts(browser, ".facts dd")
        assert any(d.endswith(FILE_A) for d in facts), facts
        if folder == "run":
            names = texts(browser, ".metrics th")
            for parked in (PARKED_A, PARKED_B):  # lengths in mm: "_mm"
                assert "parked_displacement_mm." + parked in names
        else:
            verdict = browser.js("return document.getElementById('verdict').textContent")
            assert verdict.endswith("the footprint overlaps " + ISLAND), verdict
        markup_does_not_run(browser)


def test_sweep_page_shows_names_as_text(browser, out):
    page = out / BASE_DIR / "report" / "index.html"
    open_page(browser, page)
    assert browser.js("return document.querySelector('h1 span').textContent") == SWEEP
    field = {c: browser.js("return parksimTable.getColumns().find(c => c.getDefinition().title"
                           " === arguments[0]).getField()", c) for c in ("world", "world_file")}
    cells = texts(browser, '.tabulator-cell[tabulator-field="%s"]' % field["world"])
    assert set(cells) == {WORLD_A, WORLD_B}
    files = texts(browser, '.tabulator-cell[tabulator-field="%s"]' % field["world_file"])
    assert {pathlib.PurePath(f).name for f in files} == {FILE_A, FILE_B}
    # The world's filter list, opened as a reader opens it.
    browser.js("document.querySelector('.tabulator-col[tabulator-field=\"%s\"] input')"
               ".dispatchEvent(new MouseEvent('mousedown', {bubbles: true}));"
               "document.querySelector('.tabulator-col[tabulator-field=\"%s\"] input').focus()"
               % (field["world"], field["world"]))
    items = texts(browser, ".tabulator-edit-list-item")
    assert set(items) >= {WORLD_A, WORLD_B}, items
    browser.js("document.activeElement.blur()")
    # The parked robots' columns (one world has each): chosen, their titles are the names
    # (lengths in mm: "_mm").
    for parked in (PARKED_A, PARKED_B, PARKED_C):
        name = "parked_displacement_mm." + parked
        browser.js("[...document.querySelectorAll('.chooser label')]"
                   ".find(l => l.textContent.trim() === arguments[0]).querySelector('input').click()",
                   name)
        assert name in texts(browser, ".tabulator-col-title")
    assert browser.dialogs() == []
    assert browser.console_errors() == []
    markup_does_not_run(browser)


def test_comparison_page_shows_names_as_text_and_links_files(browser, out):
    open_page(browser, out / "compare.html")
    groups = texts(browser, "#pairs .pairs h3")
    assert any(g.strip().startswith(WORLD_A + " / ") for g in groups), groups
    assert any(g.strip().startswith(WORLD_B + " / ") for g in groups), groups
    headers = texts(browser, ".tabulator-group")
    assert any(WORLD_A in h for h in headers) and any(WORLD_B in h for h in headers), headers
    baseline = browser.js("return document.querySelector('.facts dd').textContent")
    assert BASE_DIR in baseline
    # Every paired link opens the episode's page, in the folder named "javascript:...".
    links = browser.js("return [...document.querySelectorAll('#pairs a')].map(a => a.href)")
    assert links
    for link in links:
        assert link.startswith("file://"), link
        assert pathlib.Path(urllib.parse.unquote(urllib.parse.urlparse(link).path)).is_file(), link
    markup_does_not_run(browser)
