"""A real, single-node SLURM cluster on the local machine, for the tests.

``LocalSlurm`` writes a localhost ``slurm.conf`` into a private directory,
starts its own ``munged`` (private key and socket), ``slurmctld`` and
``slurmd -N localhost`` in the foreground (so their PIDs are ours) and stops
exactly those processes again, by PID, SIGKILL as the last resort.

Nothing is shared with a SLURM or MUNGE that may already run on the machine:
the daemons use their own ports, key, socket, state and log files, and every
client command is pointed at our ``slurm.conf`` through ``SLURM_CONF`` (see
``LocalSlurm.env``).

The ``slurm_cluster`` fixture (session scope) installs what is missing --
``slurm-wlm`` and ``munge`` with apt-get when running as root, and the
Snakemake SLURM executor plugin with pip -- and skips, with the reason, on a
machine without root or apt-get.  A failure to start a cluster that could be
installed is a test error, never a skip.

Import the fixture into a test module with
``from slurm_cluster import slurm_cluster  # noqa: F401``.
"""

from __future__ import annotations

import contextlib
import importlib.util
import os
import pwd
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

SLURM_BINARIES = ("sbatch", "squeue", "scontrol", "sinfo", "srun", "scancel")
DAEMONS = ("munged", "mungekey", "slurmctld", "slurmd")
APT_PACKAGES = ("slurm-wlm", "munge")
PLUGIN_MODULE = "snakemake_executor_plugin_slurm"
PLUGIN_PACKAGE = "snakemake-executor-plugin-slurm"

NODE_NAME = "localhost"
PARTITION = "debug"
# The executor plugin polls with ``squeue --states=all``, which only sees jobs
# younger than MinJobAge; it needs MinJobAge >= 3 x its first status delay.
MIN_JOB_AGE = 300


def _which(name: str) -> str | None:
    return shutil.which(name) or shutil.which(name, path="/usr/sbin:/sbin:/usr/bin:/bin")


def _missing_binaries() -> list[str]:
    return [b for b in SLURM_BINARIES + DAEMONS if _which(b) is None]


def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def install_requirements() -> None:
    """Install SLURM, MUNGE and the executor plugin if missing; skip if we cannot."""
    missing = _missing_binaries()
    if missing:
        if os.name != "posix" or os.geteuid() != 0:
            pytest.skip(
                f"real-SLURM test needs {', '.join(missing)}; not installed and not "
                "running as root, so cannot apt-get install slurm-wlm munge"
            )
        if shutil.which("apt-get") is None:
            pytest.skip(
                f"real-SLURM test needs {', '.join(missing)}; not installed and no "
                "apt-get on this machine to install slurm-wlm munge"
            )
        env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
        for cmd in (
            ["apt-get", "update", "-qq"],
            ["apt-get", "install", "-y", "-qq", "--no-install-recommends", *APT_PACKAGES],
        ):
            r = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=900)
            if r.returncode != 0:
                raise RuntimeError(f"{' '.join(cmd)} failed:\n{r.stdout[-2000:]}\n{r.stderr[-2000:]}")
        missing = _missing_binaries()
        if missing:
            raise RuntimeError(f"apt-get install {' '.join(APT_PACKAGES)} left {missing} missing")
    elif os.geteuid() != 0:
        pytest.skip("real-SLURM test starts slurmd, which must run as root; not root")

    if importlib.util.find_spec(PLUGIN_MODULE) is None:
        r = subprocess.run(
            [sys.executable, "-m", "pip", "install", "-q", PLUGIN_PACKAGE],
            capture_output=True, text=True, timeout=900,
        )
        importlib.invalidate_caches()
        if r.returncode != 0 or importlib.util.find_spec(PLUGIN_MODULE) is None:
            pytest.skip(f"cannot pip install {PLUGIN_PACKAGE}: {r.stderr.strip()[-500:]}")


def _real_memory_mb() -> int:
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemTotal:"):
                return int(line.split()[1]) // 1024
    raise RuntimeError("no MemTotal in /proc/meminfo")


class LocalSlurm:
    """One-node SLURM (plus MUNGE) in a private directory, started and stopped by PID."""

    def __init__(self, root: Path | None = None):
        # Not under pytest's tmp dirs: munged runs as user munge and must be able
        # to reach its directory, which pytest's 0700 tmp roots forbid.
        self.root = Path(root or tempfile.mkdtemp(prefix="roughcontact-slurm-"))
        self.root.chmod(0o755)
        self.cpus = os.cpu_count() or 1
        # leave some memory to the OS so that slurmd never declares the node bad
        self.memory_mb = max(512, int(_real_memory_mb() * 0.9))
        self.conf = self.root / "slurm.conf"
        self.ctld_log = self.root / "slurmctld.log"
        self.slurmd_log = self.root / "slurmd.log"
        self.munge_dir = self.root / "munge"
        self.munge_socket = self.munge_dir / "munge.socket"
        self.procs: dict[str, subprocess.Popen] = {}
        self.env = dict(os.environ, SLURM_CONF=str(self.conf))
        # never let a user's SLURM defaults (SBATCH_ACCOUNT, ...) leak in
        for k in list(self.env):
            if k.startswith(("SBATCH_", "SALLOC_", "SRUN_", "SLURM_")) and k != "SLURM_CONF":
                del self.env[k]

    # ------------------------------------------------------------------ config
    def _write_config(self) -> None:
        state = self.root / "state"
        spool = self.root / "spool"
        for d in (state, spool, spool / NODE_NAME):
            d.mkdir(exist_ok=True)
        ctld_port, slurmd_port = _free_port(), _free_port()
        while slurmd_port == ctld_port:
            slurmd_port = _free_port()
        self.conf.write_text(
            f"""\
# single-node test cluster written by tests/slurm_cluster.py
ClusterName=roughcontact-test
SlurmctldHost={NODE_NAME}(127.0.0.1)
SlurmctldPort={ctld_port}
SlurmdPort={slurmd_port}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={self.munge_socket}
StateSaveLocation={state}
SlurmdSpoolDir={spool}/%n
SlurmctldPidFile={self.root}/slurmctld.pid
SlurmdPidFile={self.root}/slurmd.pid
SlurmctldLogFile={self.ctld_log}
SlurmdLogFile={self.slurmd_log}
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
# Memory limits are enforced by polling (no cgroups in a container): every
# second each step's RSS is summed and a step above its --mem is killed
# (job state OUT_OF_MEMORY).
JobAcctGatherType=jobacct_gather/linux
JobAcctGatherFrequency=task=1
JobAcctGatherParams=OverMemoryKill
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
MinJobAge={MIN_JOB_AGE}
KillWait=5
InactiveLimit=0
SlurmctldTimeout=30
SlurmdTimeout=30
NodeName={NODE_NAME} NodeAddr=127.0.0.1 CPUs={self.cpus} RealMemory={self.memory_mb} State=UNKNOWN
PartitionName={PARTITION} Nodes={NODE_NAME} Default=YES MaxTime=INFINITE State=UP
"""
        )

    # ------------------------------------------------------------------ start
    def _spawn(self, name: str, cmd: list[str], **kw) -> subprocess.Popen:
        log = open(self.root / f"{name}.stdout", "ab")
        p = subprocess.Popen(
            cmd, env=self.env, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
            start_new_session=True, **kw,
        )
        log.close()
        self.procs[name] = p
        return p

    def _wait_for(self, what: str, ok, timeout: float = 30.0) -> None:
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            for name, p in self.procs.items():
                if p.poll() is not None:
                    raise RuntimeError(f"{name} exited with {p.returncode} while waiting for {what}:\n"
                                       + self.diagnostics())
            if ok():
                return
            time.sleep(0.3)
        raise RuntimeError(f"timed out after {timeout:.0f} s waiting for {what}:\n" + self.diagnostics())

    def _run(self, *cmd: str, check: bool = False, timeout: float = 30) -> subprocess.CompletedProcess:
        return subprocess.run(list(cmd), env=self.env, capture_output=True, text=True,
                              check=check, timeout=timeout)

    def _start_munge(self) -> None:
        munge = pwd.getpwnam("munge")
        self.munge_dir.mkdir(mode=0o700, exist_ok=True)
        key = self.munge_dir / "munge.key"
        subprocess.run([_which("mungekey"), "--create", "--keyfile", str(key)], check=True,
                       capture_output=True)
        for p in (self.munge_dir, key):
            os.chown(p, munge.pw_uid, munge.pw_gid)
        key.chmod(0o600)
        self._spawn("munged", [
            _which("munged"), "--foreground", "--force",
            f"--socket={self.munge_socket}", f"--key-file={key}",
            f"--pid-file={self.munge_dir / 'munged.pid'}",
            f"--seed-file={self.munge_dir / 'munged.seed'}",
            f"--log-file={self.munge_dir / 'munged.log'}",
        ], user=munge.pw_uid, group=munge.pw_gid, extra_groups=[], cwd=self.munge_dir)

        def ok():
            if not self.munge_socket.exists():
                return False
            enc = subprocess.run(["munge", "-n", "-S", str(self.munge_socket)], capture_output=True)
            if enc.returncode != 0:
                return False
            dec = subprocess.run(["unmunge", "-S", str(self.munge_socket)], input=enc.stdout,
                                 capture_output=True)
            return dec.returncode == 0
        self._wait_for("munged", ok)

    def _link_default_conf(self) -> None:
        # The executor plugin strips SLURM_* variables from the job environment, so the
        # `srun` inside each job finds no SLURM_CONF: expose ours at the default path,
        # but only if that path is free (never touch a real installation's config).
        self.linked_conf = None
        default = Path("/etc/slurm/slurm.conf")
        if not default.exists() and not default.is_symlink():
            default.parent.mkdir(parents=True, exist_ok=True)
            default.symlink_to(self.conf)
            self.linked_conf = default

    def start(self) -> "LocalSlurm":
        try:
            self._write_config()
            self._link_default_conf()
            self._start_munge()
            self._spawn("slurmctld", [_which("slurmctld"), "-D", "-c", "-i"])
            self._wait_for("slurmctld", lambda: self._run("scontrol", "ping").returncode == 0
                           and "UP" in self._run("scontrol", "ping").stdout)
            self._spawn("slurmd", [_which("slurmd"), "-D", "-N", NODE_NAME])

            def idle():
                r = self._run("sinfo", "-h", "-N", "-o", "%T")
                return r.returncode == 0 and r.stdout.strip().rstrip("*") in ("idle", "mixed", "allocated")
            self._wait_for("node localhost to become idle", idle, timeout=60)
        except BaseException:
            self.stop()
            raise
        return self

    # ------------------------------------------------------------------ use
    def sbatch(self, *args: str, cwd: str | os.PathLike | None = None) -> int:
        r = subprocess.run(["sbatch", "--parsable", *args], env=self.env, capture_output=True,
                           text=True, cwd=cwd, timeout=30)
        if r.returncode != 0:
            raise RuntimeError(f"sbatch {args} failed: {r.stderr}\n" + self.diagnostics())
        return int(r.stdout.strip().split(";")[0])

    def job_states(self) -> dict[int, tuple[str, str]]:
        """``{job id: (name, state)}`` of every job slurmctld still remembers."""
        r = self._run("squeue", "--states=all", "--noheader", "--format=%i|%j|%T", check=True)
        out = {}
        for line in r.stdout.splitlines():
            jid, name, state = line.strip().split("|")
            out[int(jid.split("_")[0])] = (name, state)
        return out

    def job_table(self) -> dict[int, dict[str, str]]:
        """``{job id: {name, state, comment}}`` of every job slurmctld still remembers
        (the Snakemake executor plugin puts ``rule_<rule>_wildcards_<...>`` in the comment)."""
        r = self._run("squeue", "--states=all", "--noheader", "--format=%i|%j|%T|%k", check=True)
        out = {}
        for line in r.stdout.splitlines():
            jid, name, state, comment = line.strip().split("|", 3)
            out[int(jid.split("_")[0])] = {"name": name, "state": state, "comment": comment}
        return out

    def scancel(self, job_id: int) -> None:
        """Cancel one job, as a user (or an administrator) would."""
        self._run("scancel", str(job_id), check=True)

    def wait_job(self, job_id: int, timeout: float = 60) -> str:
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            state = self.job_states().get(job_id, (None, "UNKNOWN"))[1]
            if state in ("COMPLETED", "FAILED", "CANCELLED", "TIMEOUT", "NODE_FAIL",
                         "OUT_OF_MEMORY", "BOOT_FAIL", "DEADLINE"):
                return state
            time.sleep(0.3)
        raise TimeoutError(f"job {job_id} not finished after {timeout} s:\n" + self.diagnostics())

    def started_job_ids(self) -> set[int]:
        """Job ids slurmctld's log says it allocated resources to (independent of squeue)."""
        text = self.ctld_log.read_text(errors="replace") if self.ctld_log.exists() else ""
        # the main scheduler logs "sched: Allocate JobId=N", the backfill scheduler (which starts
        # jobs when the machine is busy) "sched/backfill: _start_job: Started JobId=N"
        return {int(m) for m in re.findall(r"sched: Allocate JobId=(\d+)", text)} | \
               {int(m) for m in re.findall(r"Started JobId=(\d+)", text)} | \
               {int(m) for m in re.findall(r"JobId=(\d+) NodeList=\S+ #CPUs", text)}

    def diagnostics(self) -> str:
        parts = []
        for f in sorted(self.root.glob("*.log")) + sorted(self.root.glob("*.stdout")) + \
                [self.munge_dir / "munged.log"]:
            if f.exists():
                parts.append(f"--- {f.name} (tail) ---\n" + "\n".join(
                    f.read_text(errors="replace").splitlines()[-25:]))
        return "\n".join(parts)

    # ------------------------------------------------------------------ stop
    def stop(self) -> None:
        """Cancel our jobs, then end the daemons we started, by PID."""
        if "slurmctld" in self.procs and self.procs["slurmctld"].poll() is None:
            with contextlib.suppress(Exception):
                self._run("scancel", "--full", "--partition", PARTITION, timeout=10)
                end = time.monotonic() + 15
                while time.monotonic() < end:
                    states = {s for _, s in self.job_states().values()}
                    if not states & {"RUNNING", "PENDING", "COMPLETING", "CONFIGURING", "SUSPENDED"}:
                        break
                    time.sleep(0.5)
        # whatever job steps slurmd still tracks (reparented to init): end them by PID
        if "slurmd" in self.procs and self.procs["slurmd"].poll() is None:
            with contextlib.suppress(Exception):
                r = self._run("scontrol", "listpids", timeout=10)
                pids = {int(l.split()[0]) for l in r.stdout.splitlines()[1:] if l.split()
                        and l.split()[0].isdigit()}
                for pid in pids:
                    with contextlib.suppress(ProcessLookupError, PermissionError):
                        os.kill(pid, signal.SIGKILL)
        for name in ("slurmd", "slurmctld", "munged"):
            p = self.procs.get(name)
            if p is None:
                continue
            terminate_process(p, grace=10)
        self.procs.clear()
        link = getattr(self, "linked_conf", None)
        if link is not None and link.is_symlink() and Path(os.readlink(link)) == self.conf:
            link.unlink()
        self.linked_conf = None

    def __enter__(self) -> "LocalSlurm":
        return self.start()

    def __exit__(self, *exc) -> None:
        self.stop()


def terminate_process(p: subprocess.Popen, grace: float = 10) -> None:
    """SIGTERM ``p`` (and its process group if it leads one), SIGKILL after ``grace`` s."""
    if p.poll() is not None:
        return

    def signal_it(sig):
        with contextlib.suppress(ProcessLookupError, PermissionError):
            if os.getpgid(p.pid) == p.pid:  # started with start_new_session: its own group
                os.killpg(p.pid, sig)
            else:
                p.send_signal(sig)

    signal_it(signal.SIGTERM)
    try:
        p.wait(timeout=grace)
    except subprocess.TimeoutExpired:
        pass
    # the group may outlive its leader (children that ignored SIGTERM)
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.killpg(p.pid, signal.SIGKILL)
    with contextlib.suppress(ProcessLookupError, PermissionError):
        p.kill()
    with contextlib.suppress(subprocess.TimeoutExpired):
        p.wait(timeout=10)


@pytest.fixture(scope="session")
def slurm_cluster():
    """A running single-node SLURM for the session; skipped without root/apt-get."""
    install_requirements()
    cluster = LocalSlurm()
    cluster.start()
    try:
        yield cluster
    finally:
        cluster.stop()
        shutil.rmtree(cluster.root, ignore_errors=True)
