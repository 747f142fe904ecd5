"""A one-node SLURM on localhost for tests: munge and SLURM configured in a temporary directory,
started as child processes, stopped by their process ids. Needs Debian's slurmctld, slurmd,
slurm-client and munge (scripts/setup installs them) and root (slurmd launches jobs as their user)."""
import os
import pathlib
import shutil
import signal
import socket
import subprocess
import time

DAEMONS = ("munged", "slurmctld", "slurmd")


def available():
    """None if a one-node SLURM can run here, else the reason it cannot."""
    missing = [d for d in DAEMONS + ("sbatch", "scontrol") if not shutil.which(d, path="/usr/sbin:/usr/bin:/sbin:/bin")]
    if missing:
        return f"not installed: {', '.join(missing)} (scripts/setup installs slurmctld, slurmd, slurm-client, munge)"
    if os.geteuid() != 0:
        return "slurmd must run as root to launch jobs"
    return None


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class OneNodeSlurm:
    def __init__(self, directory):
        self.dir = pathlib.Path(directory)
        self.processes = []
        self.env = dict(os.environ)

    def write_config(self):
        d = self.dir
        for sub in ("munge", "state", "spool", "log", "run"):
            (d / sub).mkdir(parents=True, exist_ok=True)
        (d / "munge").chmod(0o700)
        key = d / "munge" / "munge.key"
        key.write_bytes(os.urandom(1024))
        key.chmod(0o400)
        host = socket.gethostname().split(".")[0]
        self.socket = d / "munge" / "munge.socket"
        self.conf = d / "slurm.conf"
        self.conf.write_text(f"""ClusterName=cellsimtest
SlurmctldHost={host}
SlurmctldPort={free_port()}
SlurmdPort={free_port()}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket={self.socket}
CredType=cred/munge
StateSaveLocation={d}/state
SlurmdSpoolDir={d}/spool
SlurmctldPidFile={d}/run/slurmctld.pid
SlurmdPidFile={d}/run/slurmd.pid
SlurmctldLogFile={d}/log/slurmctld.log
SlurmdLogFile={d}/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
MinJobAge=600
NodeName={host} NodeAddr=127.0.0.1 CPUs={os.cpu_count() or 2} RealMemory=8000 State=UNKNOWN
PartitionName=test Nodes={host} Default=YES MaxTime=INFINITE State=UP
""")
        (d / "cgroup.conf").write_text("CgroupPlugin=autodetect\nIgnoreSystemd=yes\n")
        self.env.update({"SLURM_CONF": str(self.conf), "MUNGE_SOCKET": str(self.socket)})

    def start(self, timeout=60):
        self.write_config()
        d = self.dir
        self._spawn(["munged", "-F", "--force", f"--socket={self.socket}", f"--key-file={d}/munge/munge.key",
                     f"--pid-file={d}/run/munged.pid", f"--log-file={d}/log/munged.log",
                     f"--seed-file={d}/munge/munge.seed"])
        self._wait(lambda: self.socket.exists(), timeout, "munged did not create its socket")
        self._spawn(["slurmctld", "-D", "-i", "-f", str(self.conf)])
        self._spawn(["slurmd", "-D", "-f", str(self.conf)])
        self._wait(self.node_idle, timeout, "the SLURM node did not become idle")
        return self

    def node_idle(self):
        done = subprocess.run(["sinfo", "-h", "-o", "%t"], env=self.env, capture_output=True, text=True)
        return done.returncode == 0 and done.stdout.strip().startswith("idle")

    def _spawn(self, cmd):
        log = open(self.dir / "log" / f"{cmd[0]}.stdout", "w")
        self.processes.append(subprocess.Popen(cmd, env=self.env, stdout=log, stderr=subprocess.STDOUT,
                                               start_new_session=True))

    def _wait(self, ready, timeout, what):
        deadline = time.time() + timeout
        while time.time() < deadline:
            if ready():
                return
            for p in self.processes:
                if p.poll() is not None:
                    raise RuntimeError(f"{p.args[0]} exited with {p.returncode}: {self.logs()}")
            time.sleep(0.5)
        raise RuntimeError(f"{what} within {timeout} s: {self.logs()}")

    def logs(self):
        text = []
        for f in sorted((self.dir / "log").glob("*")):
            text.append(f"--- {f.name}\n" + f.read_text()[-1500:])
        return "\n".join(text)

    def stop(self):
        """Stops the daemons this object started, by their process ids, and waits for them."""
        for p in reversed(self.processes):
            if p.poll() is None:
                p.send_signal(signal.SIGTERM)
        for p in reversed(self.processes):
            try:
                p.wait(timeout=20)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
        self.processes.clear()

    def __enter__(self):
        try:
            return self.start()
        except BaseException:
            self.stop()  # whatever did start is stopped again
            raise

    def __exit__(self, *exc):
        self.stop()
