"""CI ships what it tested: one build, tested, uploaded as the Pages artefact, and
published as it is; the tests run as README says; the browser is a step of its own;
Python comes from the locks."""

from __future__ import annotations

from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[2]
WORKFLOW = yaml.safe_load((ROOT / ".github" / "workflows" / "site.yml").read_text())


def steps(job: str) -> list[dict]:
    return WORKFLOW["jobs"][job]["steps"]


def runs(job: str) -> str:
    return "\n".join(step.get("run", "") for step in steps(job))


def test_the_test_job_tests_the_build_it_uploads():
    names = [step.get("uses", "").split("@")[0] or step.get("name", "") for step in steps("test")]
    test = next(i for i, s in enumerate(steps("test")) if s.get("run", "").strip() == "bash .ci/run")
    upload = names.index("actions/upload-pages-artifact")
    assert test < upload and steps("test")[upload]["with"]["path"] == "site"
    assert "make site" not in runs("test")  # built once, by `make test`
    assert "SITE_URL" in steps("test")[test].get("env", {})  # built for the address it is published at


def test_the_deploy_job_publishes_that_artefact_without_building():
    deploy = WORKFLOW["jobs"]["deploy"]
    assert deploy["needs"] == "test"
    assert [step["uses"].split("@")[0] for step in deploy["steps"]] == ["actions/deploy-pages"]


def test_the_browser_is_installed_by_a_named_step_and_make_test_runs_as_the_readme_says():
    browser = [s for s in steps("test") if s.get("run", "").strip() == "make browser"]
    assert len(browser) == 1 and "browser" in browser[0]["name"].lower()
    assert (ROOT / ".ci" / "run").read_text().strip().endswith("make test")
    assert "make test" in (ROOT / "README.md").read_text()


def test_python_comes_from_the_locks_only():
    makefile = (ROOT / "Makefile").read_text()
    installs = [line for line in makefile.splitlines() if "$(PIP) install" in line or "$(UV_INSTALL)" in line]
    assert len(installs) == 4  # uv from tools.lock, the two locks with uv, the package itself
    assert all("--require-hashes" in line or "-e pyodide_pkg" in line for line in installs if "$(PIP)" in line)
    uv_install = next(line for line in makefile.splitlines() if line.startswith("UV_INSTALL ="))
    assert "--require-hashes" in uv_install and "--no-deps" in uv_install
    assert "-r requirements/tools.lock" in next(line for line in installs if "--target build/tools" in line)
    for lock in ("serve.lock", "test.lock", "tools.lock"):
        lines = (ROOT / "requirements" / lock).read_text().splitlines()
        pins = [line for line in lines if "==" in line and not line.startswith(("#", " "))]
        assert pins and all(line.rstrip().endswith("\\") for line in pins), f"{lock}: every pin carries its hashes"
    assert "pytest" not in (ROOT / "requirements" / "serve.lock").read_text()  # serving installs no test tools
