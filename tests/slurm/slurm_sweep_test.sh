#!/usr/bin/env bash
# The Slurm job-array recipe of docs/planning.md, run for real on a one-node
# Slurm that this test starts and stops: a sweep of 2 sequences x 2 catheter
# positions as 4 array tasks, each one `coilsim plan`, merged per catheter
# position by `coilsim plan-merge`, must equal the single-machine `coilsim
# plan` of the same sweep (every field but the wall clocks wall_s, step_wall_s, operator_wall_s).
#
# usage: slurm_sweep_test.sh COILSIM SOURCE_DIR
# Needs munged, slurmctld, slurmd and sbatch (Debian's munge and slurm-wlm,
# scripts/bootstrap) and root (slurmd launches the tasks; CI runs as root).
# Exit 0 pass, 1 fail; the daemons are stopped whatever happens.
set -u

coilsim=$(realpath "${1:?usage: slurm_sweep_test.sh COILSIM SOURCE_DIR}")
source_dir=$(realpath "${2:?usage: slurm_sweep_test.sh COILSIM SOURCE_DIR}")

fail() { echo "slurm_sweep_test: FAIL: $*" >&2; exit 1; }

for tool in munged mungekey slurmctld slurmd sbatch squeue sinfo python3; do
  command -v "$tool" >/dev/null || fail "$tool not found: install munge and slurm-wlm (scripts/bootstrap)"
done
[ "$(id -u)" -eq 0 ] || fail "needs root: slurmd starts the tasks as their user"

work=$(mktemp -d /tmp/coilsim-slurm.XXXXXX)
chmod 700 "$work"
mkdir -p "$work/munge" "$work/state" "$work/spool" "$work/log"

# Stops what this test started (by the pid files it wrote), then removes its
# directory unless the test failed (the logs are kept for reading).
stop_daemons() {
  local code=$?
  for pidfile in "$work/slurmd.pid" "$work/slurmctld.pid" "$work/munge/munged.pid"; do
    [ -s "$pidfile" ] && kill "$(cat "$pidfile")" 2>/dev/null
  done
  for pidfile in "$work/slurmd.pid" "$work/slurmctld.pid" "$work/munge/munged.pid"; do
    [ -s "$pidfile" ] || continue
    local pid
    pid=$(cat "$pidfile")
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null
  done
  if [ "$code" -eq 0 ]; then rm -rf "$work"; else echo "slurm_sweep_test: logs kept in $work/log" >&2; fi
  exit "$code"
}
trap stop_daemons EXIT
trap 'exit 1' INT TERM

# Ports of this run's daemons: free ones, so that two runs on one machine do not meet.
read -r ctld_port slurmd_port < <(python3 -c '
import socket
socks = [socket.socket() for _ in range(2)]
for s in socks: s.bind(("127.0.0.1", 0))
print(*(s.getsockname()[1] for s in socks))')

mungekey --create --keyfile="$work/munge/munge.key" --bits=1024 || fail "mungekey could not create a key"
munged --force --socket="$work/munge/socket" --key-file="$work/munge/munge.key" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/log/munged.log" --seed-file="$work/munge/seed" \
  || fail "munged did not start (log: $work/log/munged.log)"

host=$(hostname -s)
cat >"$work/slurm.conf" <<CONF
ClusterName=coilsimtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
MailProg=/bin/true
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=1000 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=10 State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
slurmctld -i || fail "slurmctld did not start (log: $work/log/slurmctld.log)"
slurmd -N "$host" || fail "slurmd did not start (log: $work/log/slurmd.log)"
for _ in $(seq 100); do
  sinfo -h -o %T 2>/dev/null | grep -q '^idle' && break
  sleep 0.2
done
sinfo -h -o %T | grep -q '^idle' || fail "the node did not come up idle within 20 s: $(sinfo 2>&1)"

# The sweep: the 7 mm case as shipped and with its catheter tip 0.5 mm off
# the axis, times two short sequences of the catalogue's smallest coils.
nominal="$work/cases/tip-nominal.json"
moved="$work/cases/tip-moved.json"
mkdir -p "$work/cases"
python3 - "$source_dir/scenes/cases/sphere-7mm-wide-neck.json" "$nominal" "$moved" <<'PY' || fail "could not write the cases"
import json, sys
case = json.load(open(sys.argv[1]))
json.dump(case, open(sys.argv[2], "w"), indent=1)
case["scene"]["deployment"]["catheter"]["tip_position_mm"] = [0.5, 0.0, -2.0]
json.dump(case, open(sys.argv[3], "w"), indent=1)
PY
sequences="finishing-2x10,finishing-1.5x20+finishing-2x10"

# The recipe of docs/planning.md with the sweep's lists: task i plans
# sequence i % 2 from catheter position i / 2.
cat >"$work/sweep.sbatch" <<JOB
#!/bin/bash
#SBATCH --job-name=coilplan
#SBATCH --array=0-3
#SBATCH --cpus-per-task=1
#SBATCH --time=00:05:00
COILS=(finishing-2x10 finishing-1.5x20+finishing-2x10)
CASES=($nominal $moved)
NAMES=(tip-nominal tip-moved)
i=\$SLURM_ARRAY_TASK_ID
exec "$coilsim" plan "\${CASES[\$((i / 2))]}" --coils "\${COILS[\$((i % 2))]}" --no-screenshots \\
    --out "$work/sweep/\${NAMES[\$((i / 2))]}/task-\$((i % 2))"
JOB

job=$(sbatch --parsable --chdir="$work" --output="$work/log/task-%a.out" "$work/sweep.sbatch") \
  || fail "sbatch refused the job array"
echo "slurm_sweep_test: job array $job submitted"
# Meanwhile the single-machine run of the same sweep (the jobs compete for the same cores).
"$coilsim" plan "$nominal" "$moved" --coils "$sequences" --no-screenshots --out "$work/single" \
  >"$work/log/single.out" 2>&1 || fail "the single-machine plan failed: $(tail -5 "$work/log/single.out")"

for _ in $(seq 600); do
  [ -z "$(squeue -h -j "$job" 2>/dev/null)" ] && break
  sleep 0.5
done
[ -z "$(squeue -h -j "$job")" ] || fail "the job array did not finish within 300 s: $(squeue -j "$job")"
for t in 0 1 2 3; do
  state=$(scontrol show job "${job}_$t" 2>/dev/null | grep -o 'JobState=[A-Z]*' | head -1)
  # Finished jobs leave the controller after MinJobAge; the plan files below are the evidence then.
  [ -z "$state" ] || [ "$state" = JobState=COMPLETED ] || fail "task $t ended $state: $(cat "$work/log/task-$t.out")"
done

status=0
for name in tip-nominal tip-moved; do
  "$coilsim" plan-merge "$work/sweep/$name/task-0" "$work/sweep/$name/task-1" --out "$work/merged/$name" \
    >"$work/log/merge-$name.out" 2>&1 || fail "plan-merge of $name failed: $(cat "$work/log/merge-$name.out")"
  python3 - "$work/merged/$name/plan.json" "$work/single/$name/plan.json" <<'PY' || status=1
import json, sys
merged, single = (json.load(open(p)) for p in sys.argv[1:3])
def strip(plan):
    # wall_s, step_wall_s and operator_wall_s are wall clocks of each run;
    # everything else is determined by the inputs.
    clocks = ("wall_s", "step_wall_s", "operator_wall_s")
    return {"scene": plan["scene"], "sac_volume_mm3": plan["sac_volume_mm3"],
            "coils": [{k: v for k, v in c.items() if k not in clocks} for c in plan["coils"]]}
a, b = strip(merged), strip(single)
if len(a["coils"]) != 2 or any(not c["ok"] for c in a["coils"]):
    sys.exit(f"{sys.argv[1]}: expected 2 runs that worked, got {a['coils']}")
if a != b:
    for ca, cb in zip(a["coils"], b["coils"]):
        for k in sorted(set(ca) | set(cb)):
            if ca.get(k) != cb.get(k): print(f"  {ca.get('name')}: {k}: merged {ca.get(k)} single {cb.get(k)}")
    sys.exit(f"{sys.argv[1]} differs from {sys.argv[2]}")
print(f"{sys.argv[1]}: equal to the single-machine plan ({len(a['coils'])} runs, packing "
      + ", ".join(f"{c['packing_percent']:.2f} %" for c in a["coils"]) + ")")
PY
done
[ "$status" -eq 0 ] || fail "a merged plan differs from the single-machine run"
# The two catheter positions must be two outcomes, or the sweep swept nothing.
python3 - "$work/merged/tip-nominal/plan.json" "$work/merged/tip-moved/plan.json" <<'PY' || fail "the catheter positions gave the same plan"
import json, sys
clocks = ("wall_s", "step_wall_s", "operator_wall_s")
a, b = ([{k: v for k, v in c.items() if k not in clocks} for c in json.load(open(p))["coils"]] for p in sys.argv[1:3])
sys.exit(0 if a != b else 1)
PY
echo "slurm_sweep_test: 1 passed, 0 failed"
