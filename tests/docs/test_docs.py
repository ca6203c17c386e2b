"""The documentation's examples must keep working (issue 12, item 6). Every fenced block of
README.md and docs/*.md is checked by its language:

- cpp: must be an excerpt of a program under examples/ (the tests build and run those
  programs: examples/snippets/CMakeLists.txt, tests/docs/CMakeLists.txt);
- python: runs, from the source tree (a block starting "# needs: MODULE" only where MODULE is
  importable);
- yaml: a world (`format: parksim-world/1`) loads, a sweep spec (`format: parksim-sweep/1`)
  expands, a fragment of a world (realism:, tolerance:) loads when added to a study world;
- sh: every `parksim` command names a real subcommand and only options its --help lists.

Run through ctest (PARKSIM_EXE, PARKSIM_SOURCE_DIR and the module's PYTHONPATH are set there).
"""

import functools
import importlib.util
import os
import pathlib
import re
import shlex
import shutil
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("PARKSIM_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
DOCS = [SOURCE_DIR / "README.md", *sorted((SOURCE_DIR / "docs").glob("*.md"))]
FENCE = re.compile(r"^(\s*)```(\w*)\s*$")


def blocks(language):
    """(id, text) of every fenced block in `language`, the fence's indentation removed."""
    found = []
    for doc in DOCS:
        lines = doc.read_text(encoding="utf-8").splitlines()
        i = 0
        while i < len(lines):
            m = FENCE.match(lines[i])
            if not m or not m.group(2):
                i += 1
                continue
            indent, lang, start = len(m.group(1)), m.group(2), i + 1
            i += 1
            body = []
            while i < len(lines) and not FENCE.match(lines[i]):
                body.append(lines[i][indent:])
                i += 1
            i += 1  # closing fence
            if lang == language:
                found.append((f"{doc.relative_to(SOURCE_DIR)}:{start}", "\n".join(body)))
    return found


def ids(items):
    return [item[0] for item in items]


def test_the_docs_have_examples_of_each_kind():
    # Guards the extraction itself: a broken fence pattern would make every test below vacuous.
    for language, at_least in (("cpp", 3), ("python", 1), ("yaml", 3), ("sh", 10)):
        assert len(blocks(language)) >= at_least, language


# --- C++: excerpts of programs that the tests build and run --------------------------------

def significant_lines(text):
    return [line.strip() for line in text.splitlines() if line.strip()]


@functools.cache
def example_sources():
    return {path: significant_lines(path.read_text(encoding="utf-8"))
            for path in sorted((SOURCE_DIR / "examples").rglob("*.cpp"))}


def contains_run(haystack, needle):
    return any(haystack[i:i + len(needle)] == needle
               for i in range(len(haystack) - len(needle) + 1))


@pytest.mark.parametrize("where,text", blocks("cpp"), ids=ids(blocks("cpp")))
def test_cpp_block_is_an_excerpt_of_a_built_example(where, text):
    # A line "// ..." separates excerpts of one program (its includes, then its code).
    parts = [significant_lines(part) for part in re.split(r"^\s*// \.\.\.\s*$", text,
                                                          flags=re.MULTILINE)]
    homes = [p for p, lines in example_sources().items()
             if all(contains_run(lines, part) for part in parts if part)]
    assert homes, (f"{where}: this C++ block is not an excerpt of any program under examples/; "
                   "copy it from the example (between // [docs:NAME] and // [docs:end]) so it "
                   "is compiled and run by the tests")


# --- Python: every block runs ----------------------------------------------------------------

def python_sessions():
    """The Python blocks of each document, in order: a document is read like a notebook, so a
    block may use the names an earlier block of the same page defined."""
    sessions = {}
    for where, text in blocks("python"):
        sessions.setdefault(where.split(":")[0], []).append((where, text))
    return sorted(sessions.items())


@pytest.mark.parametrize("doc,session", python_sessions(), ids=[d for d, _ in python_sessions()])
def test_python_blocks_run(doc, session, monkeypatch):
    pytest.importorskip("parksim")
    monkeypatch.chdir(SOURCE_DIR)  # the examples use paths like worlds/head_in.yaml
    namespace = {"__name__": "__docs__"}
    for where, text in session:
        # A block that starts "# needs: MODULE" shows a library the project does not install
        # (no package index here, e.g. Stable-Baselines3): it runs only where that is importable.
        needs = re.match(r"# needs: ([\w.]+)", text)
        if needs and importlib.util.find_spec(needs.group(1)) is None:
            print(f"{where}: not run, {needs.group(1)} is not installed")
            continue
        exec(compile(text, where, "exec"), namespace)


# --- YAML: worlds load, sweep specs expand, fragments fit a world -----------------------------

def run_cli(*args):
    exe = os.environ.get("PARKSIM_EXE")
    if not exe:
        pytest.skip("PARKSIM_EXE is not set (run through ctest)")
    p = subprocess.run([exe, *map(str, args)], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


@pytest.mark.parametrize("where,text", blocks("yaml"), ids=ids(blocks("yaml")))
def test_yaml_block_is_valid(where, text, tmp_path):
    if re.search(r"^(stages|jobs):", text, re.MULTILINE):
        pytest.skip("a CI job, not parksim's: test_ci_examples.py parses it")
    if "format: parksim-sweep/1" in text:
        # The spec's paths are relative to the spec: put it where worlds/sweeps/ specs live, in
        # a tree like the repository's (worlds/, examples/, and build/ for plugins).
        root = tmp_path / "repo"
        (root / "worlds" / "sweeps").mkdir(parents=True)
        for world in (SOURCE_DIR / "worlds").glob("*.yaml"):
            shutil.copy(world, root / "worlds" / world.name)
        (root / "examples").symlink_to(SOURCE_DIR / "examples")
        exe = os.environ.get("PARKSIM_EXE")
        if exe:
            (root / "build").symlink_to(pathlib.Path(exe).resolve().parents[1])
        spec = root / "worlds" / "sweeps" / "doc.yaml"
        spec.write_text(text + "\n", encoding="utf-8")
        # --slurm expands and checks the whole spec but runs nothing.
        code, _, err = run_cli("sweep", spec, "--slurm", "--out", tmp_path / "out")
        assert code == 0, f"{where}: {err}"
        assert (tmp_path / "out" / "sweep.sbatch").is_file()
        return
    world = tmp_path / "doc.yaml"
    # Map worlds name their maps relative to the world file, as the shipped ones do.
    (tmp_path / "maps").symlink_to(SOURCE_DIR / "worlds" / "maps")
    if "format: parksim-world/1" in text:
        world.write_text(text + "\n", encoding="utf-8")
    else:
        # A fragment: its top-level keys are added to a study world that lacks them.
        base = (SOURCE_DIR / "worlds" / "head_in.yaml").read_text(encoding="utf-8")
        keys = re.findall(r"^(\w+):", text, re.MULTILINE)
        assert keys, f"{where}: a YAML block with no top-level key"
        for key in keys:
            assert not re.search(rf"^{key}:", base, re.MULTILINE), key
        world.write_text(base + "\n" + text + "\n", encoding="utf-8")
    # `parksim plan` with one iteration reads and checks the whole world, then stops unsolved.
    code, _, err = run_cli("plan", world, "--planner", "rrt", "--max-iterations", "1",
                           "--out", tmp_path / "plan")
    assert code in (0, 1), f"{where}: {err}"


# --- Shell: documented commands and options exist ---------------------------------------------

@functools.cache
def help_text(subcommand):
    code, out, err = run_cli(*([subcommand] if subcommand else []), "--help")
    assert code == 0, f"parksim {subcommand} --help: {err}"
    return out


def parksim_commands(text):
    """(line, words) of every parksim invocation in a shell block."""
    text = re.sub(r"\\\n", " ", text)
    found = []
    for line in text.splitlines():
        line = re.sub(r"(^|\s)#.*$", "", line)
        for part in re.split(r"&&|\|\||;|\|", line):
            try:
                words = shlex.split(part)
            except ValueError:
                words = part.split()
            if words and (words[0] in ("$B", "parksim") or words[0].endswith("app/parksim")):
                found.append((line.strip(), words[1:]))
    return found


SH_COMMANDS = [(f"{where}: {line}", words) for where, text in blocks("sh")
               for line, words in parksim_commands(text)]


def test_the_shell_blocks_call_parksim():
    assert len(SH_COMMANDS) >= 20


@pytest.mark.parametrize("where,words", SH_COMMANDS, ids=[c[0] for c in SH_COMMANDS])
def test_documented_command_exists(where, words):
    subcommand = next((w for w in words if not w.startswith("-") and not w.startswith("[")), "")
    if words and words[0].startswith("-"):
        subcommand = ""  # parksim --version
    listed = help_text(subcommand)
    if subcommand:
        assert f"parksim {subcommand}" in listed, where
    for word in words:
        for token in word.strip("[]").split("|"):
            if token.startswith("--"):
                option = token.split("=", 1)[0].rstrip("]")
                assert re.search(rf"(^|[\s,]){re.escape(option)}\b", listed, re.MULTILINE), (
                    f"{where}: parksim {subcommand} has no option {option}")


# Folders at the top of the source tree, and under parksim/ (where the docs name a source file
# relative to parksim/, as `planner/base/PlanCheck.h`).
TOP_FOLDERS = ("app/", "bench/", "cmake/", "docs/", "examples/", "parksim/", "python/",
               "scripts/", "tests/", "worlds/")
PATH_TOKEN = re.compile(r"[\w.-]+(/[\w.-]+)+\.(h|cpp|py|js|css|md|yaml|sh|txt|cmake|ipynb)")
# Paths the docs name that are not this repository's: another project's file.
NOT_OURS = {"docs/environments/parking.md"}  # highway-env's, docs/python.md


def named_paths():
    """(doc:line, path as written, where it must be) of every repository file a doc names in
    backticks (a path under a top folder, or a source file under parksim/), and every relative
    link's target."""
    parksim_folders = {p.name for p in (SOURCE_DIR / "parksim").iterdir() if p.is_dir()}
    found = []
    for doc in DOCS:
        for number, line in enumerate(doc.read_text(encoding="utf-8").splitlines(), 1):
            where = f"{doc.relative_to(SOURCE_DIR)}:{number}"
            for m in re.finditer(r"`([^`\s]+)`", line):
                token = m.group(1).rstrip(".,:;")
                if not PATH_TOKEN.fullmatch(token) or token in NOT_OURS:
                    continue
                if token.startswith(TOP_FOLDERS):
                    found.append((where, token, SOURCE_DIR / token))
                elif token.split("/")[0] in parksim_folders and token.endswith((".h", ".cpp")):
                    found.append((where, token, SOURCE_DIR / "parksim" / token))
            for m in re.finditer(r"\]\(([^)#\s]+)(#[^)]*)?\)", line):
                if "://" not in m.group(1):
                    found.append((where, m.group(1), doc.parent / m.group(1)))
    return found


def test_every_repository_path_the_docs_name_exists():
    assert len(named_paths()) > 300  # the check sees the docs' paths
    missing = [f"{where}: {token}" for where, token, path in named_paths() if not path.exists()]
    assert not missing, "named in the docs but not in the repository:\n" + "\n".join(missing)
