"""A single-node Slurm cluster on this machine, for tests (docs/sweeps.md).

Starts munged (its own key and socket), slurmctld and slurmd in a temporary
directory as children of this process, on free localhost ports, without
systemd, cgroups or accounting, and stops them whatever happens:

    with LocalSlurm(tmpdir) as env:   # env: os.environ plus SLURM_CONF
        subprocess.run(["sbatch", ...], env=env)
"""
import os
import shutil
import signal
import socket
import subprocess
import time


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def mem_mb():
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemTotal:"):
                return int(line.split()[1]) // 1024
    return 1024


class LocalSlurm:
    def __init__(self, root, cpus=2):
        self.root = os.path.abspath(root)
        # slurmd drains a node that has fewer CPUs than slurm.conf says
        self.cpus = max(1, min(cpus, os.cpu_count() or 1))
        self.procs = []

    def path(self, *p):
        return os.path.join(self.root, *p)

    def _conf(self):
        # RealMemory below the machine's so slurmd registers the node
        user = "root" if os.geteuid() == 0 else os.environ.get("USER", "nobody")
        return f"""ClusterName=mjbuoy-test
SlurmctldHost=localhost
SlurmctldPort={free_port()}
SlurmdPort={free_port()}
SlurmUser={user}
SlurmdUser={user}
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={self.path("munge.sock")}
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
StateSaveLocation={self.path("state")}
SlurmdSpoolDir={self.path("spool")}
SlurmctldPidFile={self.path("slurmctld.pid")}
SlurmdPidFile={self.path("slurmd.pid")}
SlurmctldLogFile={self.path("slurmctld.log")}
SlurmdLogFile={self.path("slurmd.log")}
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
MinJobAge=300
KillWait=5
NodeName=localhost NodeAddr=127.0.0.1 CPUs={self.cpus} RealMemory={max(256, mem_mb() // 2)} State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
"""

    def __enter__(self):
        try:
            self._start()
        except BaseException:
            self.stop()
            raise
        return self.env

    def __exit__(self, *exc):
        self.stop()
        return False

    def _spawn(self, args, name):
        log = open(self.path(name + ".out"), "w")
        p = subprocess.Popen(args, stdout=log, stderr=subprocess.STDOUT, env=self.env,
                             start_new_session=True)
        self.procs.append(p)
        return p

    def _start(self):
        for d in ("state", "spool", "munge"):
            os.makedirs(self.path(d), exist_ok=True)
        os.chmod(self.path("munge"), 0o700)
        key = self.path("munge", "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o400)
        conf = self.path("slurm.conf")
        with open(conf, "w") as f:
            f.write(self._conf())
        self.env = dict(os.environ, SLURM_CONF=conf)
        self._spawn(["munged", "--foreground", "--force", "--key-file", key,
                     "--socket", self.path("munge.sock"),
                     "--pid-file", self.path("munge", "munged.pid"),
                     "--log-file", self.path("munge", "munged.log"),
                     "--seed-file", self.path("munge", "munged.seed")], "munged")
        self._wait(lambda: os.path.exists(self.path("munge.sock")), 10, "munged socket")
        self._spawn(["slurmctld", "-D", "-i", "-f", conf], "slurmctld")
        self._spawn(["slurmd", "-D", "-f", conf], "slurmd")
        self._wait(self._node_up, 60, "node localhost idle in sinfo")

    def _node_up(self):
        for p in self.procs:
            if p.poll() is not None:
                raise RuntimeError(f"{p.args[0]} exited with {p.returncode}: " + self.logs())
        r = subprocess.run(["sinfo", "-h", "-N", "-o", "%T"], env=self.env,
                           capture_output=True, text=True)
        return r.returncode == 0 and r.stdout.strip() in ("idle", "mixed", "allocated")

    def _wait(self, cond, timeout, what):
        t0 = time.time()
        while time.time() - t0 < timeout:
            if cond():
                return
            time.sleep(0.2)
        raise RuntimeError(f"timed out after {timeout} s waiting for {what}: " + self.logs())

    def logs(self):
        out = []
        for n in ("munged.out", "slurmctld.out", "slurmd.out", "slurmctld.log", "slurmd.log"):
            p = self.path(n)
            if os.path.exists(p):
                with open(p, errors="replace") as f:
                    out.append(f"--- {n}\n" + "".join(f.readlines()[-15:]))
        return "\n".join(out)

    def stop(self):
        # cancel what still runs (slurmstepd leaves slurmd's process group),
        # then slurmd, slurmctld and munged
        if self.procs and all(p.poll() is None for p in self.procs):
            subprocess.run(["scancel", "--partition=test"], env=self.env, capture_output=True,
                           timeout=10)
            t0 = time.time()
            while time.time() - t0 < 10:
                q = subprocess.run(["squeue", "-h"], env=self.env, capture_output=True, text=True)
                if q.returncode != 0 or not q.stdout.strip():
                    break
                time.sleep(0.2)
        for p in reversed(self.procs):
            if p.poll() is None:
                try:
                    os.killpg(p.pid, signal.SIGTERM)
                except ProcessLookupError:
                    pass
                try:
                    p.wait(10)
                except subprocess.TimeoutExpired:
                    os.killpg(p.pid, signal.SIGKILL)
                    p.wait()
        self.procs = []
