"""A throw-away one-node Slurm cluster on this machine, for the workflow's Slurm test.

`SlurmCluster(folder)` writes everything under `folder`: a munge key, socket, pid, seed and log;
a slurm.conf (this host as controller and only node, CPUs from nproc, RealMemory from
/proc/meminfo, one partition, auth/munge through our own socket, state, spool, pid and log files
in the folder, proctrack/linuxproc, task/none, select/cons_tres, no accounting, and
jobcomp/filetxt so that every finished job is logged without slurmdbd); ports are the first two
free ones from 16817 up, so a system slurmctld/slurmd (6817/6818) or munged (/run/munge) that a
package installed is neither used nor disturbed.

`start()` runs munged, slurmctld and slurmd in the foreground as our own child processes and
waits (bounded) until sinfo shows the node idle; it raises RuntimeError with the daemons' logs when
they do not come up. `stop()` ends them (SIGTERM, then SIGKILL after a grace period), also any
pid named in their pid files and any slurmstepd or slurmscriptd that appeared since start(), and
returns the pids
still alive (none when all went). `env()` is the environment for sbatch, squeue, scontrol and
snakemake (SLURM_CONF).
"""

import os
import signal
import socket
import subprocess
import time

START_TIMEOUT_S = 60  # the daemons are up in ~3 s here; a minute allows for a loaded machine
STOP_GRACE_S = 10  # SIGTERM, then SIGKILL
FIRST_PORT = 16817  # far from Slurm's 6817/6818


def free_ports(count, first=FIRST_PORT, last=FIRST_PORT + 200):
    ports = []
    for port in range(first, last):
        with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as probe:
            try:
                probe.bind(("", port))
            except OSError:
                continue
        ports.append(port)
        if len(ports) == count:
            return ports
    raise RuntimeError(f"no {count} free TCP ports in {first}-{last}")


def processes_named(name):
    pids = set()
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/comm") as handle:
                    if handle.read().strip() == name:
                        pids.add(int(entry))
            except OSError:
                pass
    return pids


def alive(pid):
    try:
        with open(f"/proc/{pid}/stat") as handle:
            return handle.read().split(")")[-1].split()[0] != "Z"  # a zombie has ended
    except OSError:
        return False


class SlurmCluster:
    def __init__(self, folder):
        self.folder = os.path.abspath(folder)
        self.host = socket.gethostname().split(".")[0]
        self.children = {}  # name -> Popen
        self.stepd_before = set()
        self.paths = {name: os.path.join(self.folder, name) for name in (
            "munge", "state", "spool", "log", "run", "slurm.conf")}
        self.munge_socket = os.path.join(self.paths["munge"], "munge.socket")
        self.jobcomp = os.path.join(self.paths["log"], "jobcomp.txt")

    def env(self):
        return dict(os.environ, SLURM_CONF=self.paths["slurm.conf"])

    def log_file(self, name):
        return os.path.join(self.paths["log"], name + ".log")

    def write_config(self):
        os.makedirs(self.folder, exist_ok=True)
        os.chmod(self.folder, 0o755)  # munged needs execute permission for all on the socket's parents
        for name in ("munge", "state", "spool", "log", "run"):
            os.makedirs(self.paths[name], mode=0o755, exist_ok=True)
            os.chmod(self.paths[name], 0o755)
        key = os.path.join(self.paths["munge"], "munge.key")
        with open(key, "wb") as handle:
            handle.write(os.urandom(1024))  # what `mungekey` or `dd if=/dev/urandom bs=1024 count=1` make
        os.chmod(key, 0o400)
        ctld_port, d_port = free_ports(2)
        mem_mb = int(open("/proc/meminfo").read().split("MemTotal:")[1].split()[0]) // 1024
        real_mb = mem_mb * 95 // 100  # below what slurmd measures, or it drains the node (Low RealMemory)
        run, log = self.paths["run"], self.paths["log"]
        lines = [
            "ClusterName=sgptest", f"SlurmctldHost={self.host}", "SlurmUser=root", "SlurmdUser=root",
            f"SlurmctldPort={ctld_port}", f"SlurmdPort={d_port}",
            "AuthType=auth/munge", "CredType=cred/munge", f"AuthInfo=socket={self.munge_socket}",
            f"StateSaveLocation={self.paths['state']}", f"SlurmdSpoolDir={self.paths['spool']}",
            f"SlurmctldPidFile={run}/slurmctld.pid", f"SlurmdPidFile={run}/slurmd.pid",
            f"SlurmctldLogFile={log}/slurmctld.log", f"SlurmdLogFile={log}/slurmd.log",
            "ProctrackType=proctrack/linuxproc", "TaskPlugin=task/none",
            "SelectType=select/cons_tres", "SelectTypeParameters=CR_Core_Memory",
            "JobCompType=jobcomp/filetxt", f"JobCompLoc={self.jobcomp}",
            "JobAcctGatherType=jobacct_gather/none", "AccountingStorageType=accounting_storage/none",
            "MpiDefault=none", "SwitchType=switch/none", "ReturnToService=2", "SlurmctldTimeout=30",
            "MailProg=/bin/true",  # Debian ships no mail program; slurmctld complains without one
            "MinJobAge=300",  # scontrol remembers a finished job 5 min: what the cluster-status script asks
            f"NodeName={self.host} CPUs={os.cpu_count()} RealMemory={real_mb} State=UNKNOWN",
            f"PartitionName=test Nodes={self.host} Default=YES MaxTime=INFINITE State=UP",
        ]
        with open(self.paths["slurm.conf"], "w") as handle:
            handle.write("\n".join(lines) + "\n")

    def spawn(self, name, argv):
        out = open(self.log_file(name + "-console"), "w")
        self.children[name] = subprocess.Popen(argv, stdout=out, stderr=subprocess.STDOUT,
                                               stdin=subprocess.DEVNULL, env=self.env())
        out.close()

    def start(self):
        self.write_config()
        self.stepd_before = processes_named("slurmstepd") | processes_named("slurmscriptd")
        munge = self.paths["munge"]
        self.spawn("munged", ["munged", "--foreground", f"--socket={self.munge_socket}",
                              f"--key-file={munge}/munge.key", f"--pid-file={munge}/munged.pid",
                              f"--log-file={self.log_file('munged')}", f"--seed-file={munge}/munged.seed"])
        self.wait_for(lambda: os.path.exists(self.munge_socket), "munged's socket")
        conf = self.paths["slurm.conf"]
        self.spawn("slurmctld", ["slurmctld", "-D", "-f", conf])
        self.wait_for(lambda: self.query(["scontrol", "ping"]).count("UP") > 0, "slurmctld answering scontrol ping")
        self.spawn("slurmd", ["slurmd", "-D", "-f", conf])
        self.wait_for(lambda: "idle" in self.query(["sinfo", "-h", "-N", "-o", "%T"]), "the node idle in sinfo")

    def query(self, argv):
        try:
            return subprocess.run(argv, capture_output=True, text=True, timeout=20, env=self.env()).stdout
        except (OSError, subprocess.TimeoutExpired):
            return ""

    def wait_for(self, ready, what):
        deadline = time.monotonic() + START_TIMEOUT_S
        while time.monotonic() < deadline:
            if ready():
                return
            ended = [name for name, child in self.children.items() if child.poll() is not None]
            if ended:
                raise RuntimeError(f"{', '.join(ended)} exited while waiting for {what}\n{self.logs()}")
            time.sleep(0.5)
        raise RuntimeError(f"no {what} after {START_TIMEOUT_S} s\n{self.logs()}")

    def logs(self, tail_chars=3000):
        parts = []
        for name in sorted(os.listdir(self.paths["log"]) if os.path.isdir(self.paths["log"]) else []):
            text = open(os.path.join(self.paths["log"], name), errors="replace").read()
            parts.append(f"--- {name} (last {tail_chars} characters) ---\n{text[-tail_chars:]}")
        return "\n".join(parts)

    def pid_file_pids(self):
        pids = []
        for path in (f"{self.paths['run']}/slurmd.pid", f"{self.paths['run']}/slurmctld.pid",
                     f"{self.paths['munge']}/munged.pid"):
            try:
                pids.append(int(open(path).read().split()[0]))
            except (OSError, ValueError, IndexError):
                pass
        return pids

    def stop(self):
        """Ends every daemon started here, slurmd first; returns the pids that are still alive."""
        ours = [child.pid for name, child in sorted(self.children.items(), key=lambda item: item[0] != "slurmd")]
        ours += [pid for pid in self.pid_file_pids() if pid not in ours]
        ours += sorted((processes_named("slurmstepd") | processes_named("slurmscriptd")) - self.stepd_before)
        for pid in ours:
            if alive(pid):
                os.kill(pid, signal.SIGTERM)
        deadline = time.monotonic() + STOP_GRACE_S
        while time.monotonic() < deadline and any(alive(pid) for pid in ours):
            for child in self.children.values():
                child.poll()  # reap our children, so that they do not linger as zombies
            time.sleep(0.2)
        for pid in ours:
            if alive(pid):
                os.kill(pid, signal.SIGKILL)
        for child in self.children.values():
            try:
                child.wait(timeout=STOP_GRACE_S)
            except subprocess.TimeoutExpired:
                pass
        time.sleep(0.2)
        return [pid for pid in ours if alive(pid)]
