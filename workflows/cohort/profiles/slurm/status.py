#!/usr/bin/python3
"""Snakemake cluster-status for Slurm without accounting: prints running, success or failed.

Usage: status.py JOBID   (Snakemake 7 calls it as `cluster-status` with the id sbatch printed)

Asks `scontrol show job -o JOBID`, which knows a job while it is queued or running and for
MinJobAge seconds (default 300) after it ends; that needs no slurmdbd, unlike `sacct`. When
scontrol has forgotten the job, `sacct` is tried (it answers where accounting exists); when neither
knows it, the job ended long ago and "success" is printed: Snakemake then checks that the job's
outputs exist and fails the job if they do not, so a lost job is never taken for a planned case.
A job killed by Slurm (time limit, memory, node failure, scancel) is "failed", which Snakemake's
marker files alone would never notice. When the controller does not answer at all, "running" is
printed, so that a restarting slurmctld does not fail the cohort's jobs.
"""

import subprocess
import sys

RUNNING = {"PENDING", "CONFIGURING", "RUNNING", "COMPLETING", "SUSPENDED", "REQUEUED", "RESIZING",
           "SIGNALING", "STAGE_OUT", "REQUEUE_HOLD", "REQUEUE_FED", "RESV_DEL_HOLD", "STOPPED"}
SUCCESS = {"COMPLETED"}
FORGOTTEN = "forgotten"


def classify(state):
    """A Slurm job state (e.g. 'CANCELLED by 0') -> running | success | failed."""
    state = state.split()[0].rstrip("+") if state.strip() else ""
    if state in RUNNING:
        return "running"
    if state in SUCCESS:
        return "success"
    return "failed"  # FAILED, TIMEOUT, CANCELLED, OUT_OF_MEMORY, NODE_FAIL, BOOT_FAIL, DEADLINE, PREEMPTED


def scontrol_state(job_id):
    """The job's state; FORGOTTEN when the controller no longer knows the id; None when the
    controller cannot be asked (then the job is taken as still running, and asked again later)."""
    try:
        out = subprocess.run(["scontrol", "show", "job", "-o", job_id], capture_output=True, text=True,
                             timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        return None
    for field in out.stdout.split():
        if field.startswith("JobState="):
            return field.split("=", 1)[1]
    return FORGOTTEN if "invalid job id" in out.stderr.lower() else None


def sacct_state(job_id):
    try:
        out = subprocess.run(["sacct", "-n", "-X", "-P", "-o", "State", "-j", job_id], capture_output=True,
                             text=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        return None
    lines = [line.strip() for line in out.stdout.splitlines() if line.strip()]
    return lines[0] if out.returncode == 0 and lines else None


def main():
    if len(sys.argv) != 2:
        print(__doc__.splitlines()[2], file=sys.stderr)
        return 2
    job_id = sys.argv[1].strip().split(";")[0]  # --parsable prints "id" or "id;cluster"
    state = scontrol_state(job_id)
    if state is None:
        print("running")  # the controller did not answer: ask again at the next poll
        return 0
    if state == FORGOTTEN:
        state = sacct_state(job_id)
    print(classify(state) if state else "success")
    return 0


if __name__ == "__main__":
    sys.exit(main())
