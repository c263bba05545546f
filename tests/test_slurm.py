"""The pipeline on a real single-node SLURM (slurm-wlm + munge on localhost).

Select with ``pytest -m slurm``, leave out with ``-m "not slurm"``; runs by
default.  Skipped, with the reason, on a machine without root or apt-get
(see tests/slurm_cluster.py).
"""

from __future__ import annotations

import pytest

from slurm_cluster import slurm_cluster  # noqa: F401  (fixture)

pytestmark = pytest.mark.slurm


def test_trivial_job_runs_through_slurm(slurm_cluster, tmp_path):  # noqa: F811
    out = tmp_path / "job-%j.out"
    jid = slurm_cluster.sbatch("--wrap", "echo job=$SLURM_JOB_ID node=$SLURMD_NODENAME; srun true",
                               "-o", str(out), "--cpus-per-task=1", "--mem=100",
                               cwd=tmp_path)
    assert slurm_cluster.wait_job(jid) == "COMPLETED"
    assert (tmp_path / f"job-{jid}.out").read_text().split() == [f"job={jid}", "node=localhost"]
    assert jid in slurm_cluster.started_job_ids()
