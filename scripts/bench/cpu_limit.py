"""A phone-class CPU for the whole browser: every process of it in a CPU cgroup.

CDP's ``Emulation.setCPUThrottlingRate`` slows a page's main thread only; Chromium
refuses it for workers, so a bench that uses it alone measures Pyodide's start (which
runs in our worker) at desktop speed. Here the browser is started through a small
wrapper that first moves itself into a cgroup whose CPU quota is ``share`` of one core
(``cpu.max`` on cgroup v2, ``cpu.cfs_quota_us`` on v1), then ``exec``s Chromium: every
process Chromium starts (renderers, their workers, the GPU and network services)
inherits the cgroup, so all of them together get that share.

Needs permission to create a cgroup (root, or a delegated subtree). Where that is
refused, :func:`open_limit` returns None and the caller falls back to CDP throttling,
saying so in the report.
"""

from __future__ import annotations

import os
import shlex
import stat
import tempfile
from dataclasses import dataclass
from pathlib import Path

ROOT_V2 = Path("/sys/fs/cgroup")
ROOT_V1 = Path("/sys/fs/cgroup/cpu")
PERIOD_US = 100_000


@dataclass
class CpuLimit:
    """A cgroup holding at most `share` of one core, and the wrapper that starts a program in it."""

    group: Path
    share: float
    wrapper: Path
    version: int

    def describe(self) -> str:
        return (f"every browser process in one cgroup (v{self.version}, {self.group}) limited to "
                f"{self.share:g} of one core ({int(self.share * PERIOD_US)} us per {PERIOD_US} us period)")

    def close(self) -> None:
        """Remove the wrapper and the cgroup (once the browsers in it have exited)."""
        self.wrapper.unlink(missing_ok=True)
        parent = self.group.parent / "cgroup.procs"
        try:
            for pid in (self.group / "cgroup.procs").read_text().split():
                try:
                    parent.write_text(pid)  # a straggler: out of the group, so the group can go
                except OSError:
                    pass
            self.group.rmdir()
        except OSError:
            pass


def _make_group(share: float) -> tuple[Path, int] | None:
    quota = int(share * PERIOD_US)
    name = f"wb-bench-{os.getpid()}"
    v2 = ROOT_V2 / "cgroup.controllers"
    if v2.exists() and "cpu" in v2.read_text().split():
        try:
            (ROOT_V2 / "cgroup.subtree_control").write_text("+cpu")
        except OSError:
            pass
        group = ROOT_V2 / name
        try:
            group.mkdir(exist_ok=True)
            (group / "cpu.max").write_text(f"{quota} {PERIOD_US}")
            return group, 2
        except OSError:
            _remove(group)
    if (ROOT_V1 / "cpu.cfs_quota_us").exists():
        group = ROOT_V1 / name
        try:
            group.mkdir(exist_ok=True)
            (group / "cpu.cfs_period_us").write_text(str(PERIOD_US))
            (group / "cpu.cfs_quota_us").write_text(str(quota))
            return group, 1
        except OSError:
            _remove(group)
    return None


def _remove(group: Path) -> None:
    try:
        group.rmdir()
    except OSError:
        pass


def open_limit(executable: str, share: float) -> CpuLimit | None:
    """A cgroup at `share` of a core and a wrapper that runs `executable` inside it, or None if refused."""
    made = _make_group(share)
    if made is None:
        return None
    group, version = made
    fd, path = tempfile.mkstemp(prefix="wb-bench-cpu-", suffix=".sh")
    script = (f"#!/bin/sh\n# the bench's phone CPU: join the group, then become the browser\n"
              f"echo $$ > {shlex.quote(str(group / 'cgroup.procs'))} || exit 97\n"
              f"exec {shlex.quote(executable)} \"$@\"\n")
    with os.fdopen(fd, "w") as f:
        f.write(script)
    wrapper = Path(path)
    wrapper.chmod(wrapper.stat().st_mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)
    return CpuLimit(group, share, wrapper, version)
