#!/usr/bin/env bash
# A real single-node Slurm cluster from Debian's packages (slurmctld, slurmd, munge), started as
# root with its configuration and state under WORK; submits scripts/slurm/campaign.sbatch as a
# 4-task job array, waits, merges the shards with `highlift campaign merge` and checks that the
# merged summary (envelope, case peaks, failures) equals a local run's exactly. Tears the cluster
# down on every exit. Exit 77 (ctest: skipped) only where Slurm is not installed or not root.
#
#   slurm_cluster_test.sh HIGHLIFT_CLI SOURCE_DIR WORK
set -euo pipefail
HIGHLIFT=$(realpath "$1")
SOURCE=$(realpath "$2")
WORK=$3

skip() { echo "SKIPPED: $*"; exit 77; }
fail() { echo "FAILED: $*"; for f in "$WORK"/log/*.log; do echo "--- $f"; tail -n 30 "$f"; done; exit 1; }

[ "$(id -u)" -eq 0 ] || skip "the single-node Slurm cluster runs its daemons as root; run the test as root"
for tool in slurmctld slurmd sbatch squeue scontrol munged munge; do
  command -v "$tool" > /dev/null ||
    skip "Slurm is not installed ('$tool' not found): scripts/install-deps.sh installs the Debian packages slurmctld slurmd slurm-client munge"
done

# Campaign of the test: reduced model, 3 jams x (nominal + 3 Sobol points) = 12 runs.
PROJECT=$SOURCE/examples/a380_class_flaps.json
OPTIONS="--cases jam_l1,jam_l2,jam_r3 --samples 3 --seed 11 --model reduced"

rm -rf "$WORK"
mkdir -p "$WORK"/{etc,state,spool,log,out,local}
export SLURM_CONF=$WORK/etc/slurm.conf
started_munged=""
cleanup() {
  set +e
  scancel --full --quiet --user=root 2> /dev/null
  for daemon in slurmd slurmctld; do
    [ -f "$WORK/$daemon.pid" ] && kill "$(cat "$WORK/$daemon.pid")" 2> /dev/null
  done
  sleep 0.5
  for daemon in slurmd slurmctld; do
    [ -f "$WORK/$daemon.pid" ] && kill -9 "$(cat "$WORK/$daemon.pid")" 2> /dev/null
  done
  [ -n "$started_munged" ] && kill "$started_munged" 2> /dev/null
}
trap cleanup EXIT

# munge: the authentication Slurm uses. Reuse a running munged, else start one as the munge user.
if ! munge -n 2> /dev/null | unmunge > /dev/null 2>&1; then
  mkdir -p /run/munge /var/log/munge /var/lib/munge
  chown munge:munge /run/munge /var/log/munge /var/lib/munge
  chmod 0755 /run/munge
  if [ ! -s /etc/munge/munge.key ]; then
    mkdir -p /etc/munge
    dd if=/dev/urandom of=/etc/munge/munge.key bs=1 count=128 status=none
    chown munge:munge /etc/munge/munge.key
    chmod 0400 /etc/munge/munge.key
  fi
  runuser -u munge -- munged --force
  for _ in $(seq 50); do [ -f /run/munge/munged.pid ] && break; sleep 0.1; done
  started_munged=$(cat /run/munge/munged.pid 2> /dev/null || true)
  munge -n | unmunge > /dev/null || fail "munged does not answer"
fi

# Ports of our own (another cluster of this test may run beside it).
base=$((20000 + ($$ % 20000)))
node=$(hostname -s)
node_line=$(slurmd -C | head -n 1)  # NodeName=... CPUs=... RealMemory=...
cat > "$SLURM_CONF" << EOF
ClusterName=highlift-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$base
SlurmdPort=$((base + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
StateSaveLocation=$WORK/state
SlurmdSpoolDir=$WORK/spool
SlurmctldPidFile=$WORK/slurmctld.pid
SlurmdPidFile=$WORK/slurmd.pid
SlurmctldLogFile=$WORK/log/slurmctld.log
SlurmdLogFile=$WORK/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
MinJobAge=300
$node_line NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF

slurmctld -f "$SLURM_CONF" || fail "slurmctld did not start"
slurmd -f "$SLURM_CONF" || fail "slurmd did not start"
for _ in $(seq 150); do
  state=$(sinfo --noheader --format=%t 2> /dev/null | head -n 1 || true)
  [ "$state" = "idle" ] && break
  sleep 0.2
done
[ "$state" = "idle" ] || fail "the node did not become idle (state '$state')"
echo "cluster up: $(sinfo --noheader --format='%P %D %t %c CPUs')"

# The job array: 4 shards, each task `highlift campaign` with the shard from SLURM_ARRAY_TASK_*.
cd "$WORK"
start=$(date +%s%N)
# The variables go through the environment (--export=ALL): --export=NAME=value splits at commas.
HIGHLIFT=$HIGHLIFT PROJECT=$PROJECT OUT=$WORK/out CAMPAIGN_OPTIONS=$OPTIONS \
  timeout 120 sbatch --wait --array=0-3 --cpus-per-task=1 --output="$WORK/log/task-%a.log" --export=ALL \
  "$SOURCE/scripts/slurm/campaign.sbatch" || fail "the job array failed"
end=$(date +%s%N)
echo "job array of 4 tasks done in $(((end - start) / 1000000)) ms"
ls "$WORK/out"
[ "$(ls "$WORK"/out/campaign-shard-*-of-4.sqlite | wc -l)" -eq 4 ] || fail "expected 4 shard files"

set +e
"$HIGHLIFT" campaign merge "$WORK/out" --json > "$WORK/merged.json"
rc=$?
# shellcheck disable=SC2086
(set -f; "$HIGHLIFT" campaign "$PROJECT" --out "$WORK/local" $OPTIONS --json > "$WORK/local.json" 2> "$WORK/log/local.log")
local_rc=$?
set -e
[ $rc -le 1 ] || fail "merge exited with $rc"
[ $local_rc -le 1 ] || fail "the local run exited with $local_rc"
grep -v '"file":' "$WORK/merged.json" > "$WORK/merged.cmp"
grep -v '"file":' "$WORK/local.json" > "$WORK/local.cmp"
grep -q '"runs_done": 12,' "$WORK/merged.cmp" || fail "the merged campaign does not hold 12 runs"
grep -q '"cases": 3,' "$WORK/merged.cmp" || fail "the merged campaign does not hold 3 cases"
grep -q '"envelope": \[' "$WORK/merged.cmp" || fail "no envelope in the merged summary"
diff "$WORK/local.cmp" "$WORK/merged.cmp" || fail "the merged envelope differs from the local run's"
echo "PASSED: the merged envelope of the 4-task job array equals the local run's"

# Measurement, not part of the test: HIGHLIFT_SLURM_SCALING="1 2 4" runs a larger campaign
# (HIGHLIFT_SLURM_SCALING_OPTIONS; by default the reduced model, 24 cases x the nominal point and
# the 4 corners of two PDU parameters, 120 runs) as job arrays of that many 1-CPU
# tasks and prints, per array, the time from submission until the queue is empty (polled every
# 0.1 s: `sbatch --wait` polls in steps of seconds) and each task's own campaign wall time
# (docs/performance.md).
for tasks in ${HIGHLIFT_SLURM_SCALING:-}; do
  scaling_options=${HIGHLIFT_SLURM_SCALING_OPTIONS:-"--cases jam_*,rupture_shaft_l* --corners pdu.motor_inertia,pdu.brake_torque --model reduced"}
  start=$(date +%s%N)
  job=$(HIGHLIFT=$HIGHLIFT PROJECT=$PROJECT OUT=$WORK/scaling-$tasks CAMPAIGN_OPTIONS=$scaling_options \
    sbatch --parsable --array=0-$((tasks - 1)) --cpus-per-task=1 --output="$WORK/log/scaling-$tasks-%a.log" \
    --export=ALL "$SOURCE/scripts/slurm/campaign.sbatch") || fail "the scaling array of $tasks tasks was not submitted"
  for _ in $(seq 30000); do
    [ -z "$(squeue --noheader --jobs="${job%%;*}" 2> /dev/null)" ] && break
    sleep 0.1
  done
  end=$(date +%s%N)
  walls=$(for f in "$WORK"/log/scaling-"$tasks"-*.log; do tail -n 1 "$f"; done | grep -o '[0-9.]* s wall' | tr '\n' ' ')
  echo "scaling: $tasks task(s) x 1 CPU: $(((end - start) / 1000000)) ms from submission to an empty queue; the tasks' campaigns: ${walls:-?} for '$scaling_options' (load $(cut -d' ' -f1-3 /proc/loadavg))"
done
