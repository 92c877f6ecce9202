#!/usr/bin/env bash
# A real one-node Slurm cluster on localhost (munged, slurmctld, slurmd, configured in a temporary
# folder): `hullpack batch --shards 4 --slurm` over generated assets must give outputs
# byte-identical to a one-machine `hullpack batch`, and the merge job's summary must list every
# asset. Every daemon the test starts is stopped, also on failure. Exit 77 (skipped) only when the
# daemons cannot start here: not root, or slurm-wlm/munge not installed.
# usage: slurm_batch_test.sh HULLPACK_BINARY SOURCE_DIR
set -u
bin=$1
src=$2
skip() {
  echo "SKIPPED: $*"
  exit 77
}
[ "$(id -u)" = 0 ] || skip "starting slurmctld, slurmd and munged needs root"
for p in munged slurmctld slurmd sbatch squeue sinfo; do
  command -v "$p" >/dev/null || skip "$p not found (Debian packages slurm-wlm and munge)"
done

tmp=$(mktemp -d /tmp/hullpack-slurm.XXXXXX)
chmod 711 "$tmp"  # munged wants its socket's folder searchable
pids=()
cleanup() {
  local pid
  # Jobs first (this cluster's only), so that no slurmstepd outlives slurmd.
  [ -S "$tmp/munge.socket" ] && scancel --quiet --user=root >/dev/null 2>&1 && sleep 0.5
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null
  done
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() {
  echo "FAIL $*"
  for log in "$tmp"/*.log "$tmp"/cluster/.hullpack-batch/*.log; do
    [ -f "$log" ] && { echo "--- $log"; tail -n 20 "$log"; }
  done
  exit 1
}

host=$(hostname -s)
cpus=$(nproc)
# Two free ports next to each other (a connect that succeeds means the port is taken).
port_taken() { (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
for _ in $(seq 20); do
  port=$((20000 + RANDOM % 20000))
  port_taken "$port" || port_taken $((port + 1)) || break
done
mkdir -p "$tmp/state" "$tmp/spool"
dd if=/dev/urandom of="$tmp/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge.key"
cat >"$tmp/slurm.conf" <<CONF
ClusterName=hullpacktest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.socket
SlurmctldPort=$port
SlurmdPort=$((port + 1))
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=batch Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
cat >"$tmp/cgroup.conf" <<CONF
CgroupAutomount=no
CONF
export SLURM_CONF=$tmp/slurm.conf

munged -F --force --key-file="$tmp/munge.key" --socket="$tmp/munge.socket" \
  --pid-file="$tmp/munged.pid" --log-file="$tmp/munged.log" --seed-file="$tmp/munged.seed" \
  >"$tmp/munged.out" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$tmp/munge.socket" ] && break; sleep 0.1; done
[ -S "$tmp/munge.socket" ] || fail "munged did not start"
slurmctld -D -i -f "$tmp/slurm.conf" >"$tmp/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$tmp/slurm.conf" -N "$host" >"$tmp/slurmd.out" 2>&1 &
pids+=($!)
up=
for _ in $(seq 150); do
  state=$(sinfo -h -o %T -n "$host" 2>/dev/null)
  case "$state" in idle*|mix*|alloc*) up=1; break ;; esac
  sleep 0.2
done
[ -n "$up" ] || fail "the node did not come up (state '$state')"

"$src/tests/tools/batch/make_assets.sh" "$tmp/assets" 32
(cd "$tmp/assets" && ls *.obj) >"$tmp/assets/manifest.txt"
options=(--resolution 20000 --max-hulls 8)

"$bin" batch --manifest "$tmp/assets/manifest.txt" -o "$tmp/local" --quiet "${options[@]}" \
  >"$tmp/local.out" 2>&1 || fail "one-machine batch: $(cat "$tmp/local.out")"
"$bin" batch --manifest "$tmp/assets/manifest.txt" -o "$tmp/cluster" "${options[@]}" \
  --shards 4 --slurm --time=10 >"$tmp/submit.out" 2>&1 || fail "submission: $(cat "$tmp/submit.out")"
array=$(sed -n 's/^array job \([0-9]*\):.*/\1/p' "$tmp/submit.out")
merge=$(sed -n 's/^merge job \([0-9]*\):.*/\1/p' "$tmp/submit.out")
[ -n "$array" ] && [ -n "$merge" ] || fail "no job ids in: $(cat "$tmp/submit.out")"
tasks=$(squeue -h -r -j "$array" -o %i 2>/dev/null | wc -l)
echo "array job $array ($tasks tasks queued or running), merge job $merge"
done=
for _ in $(seq 600); do
  if [ -z "$(squeue -h -j "$array,$merge" -o %i 2>/dev/null)" ]; then done=1; break; fi
  sleep 0.2
done
[ -n "$done" ] || fail "the jobs did not finish within 120 s"

for k in 0 1 2 3; do
  [ -f "$tmp/cluster/.hullpack-batch/summary-$k-of-4.json" ] || fail "shard $k wrote no summary"
done
[ -f "$tmp/cluster/summary.json" ] || fail "the merge job wrote no summary"
listed=$(grep -c '"input":' "$tmp/cluster/summary.json")
[ "$listed" = 32 ] || fail "the merged summary lists $listed assets, not 32"
[ "$(grep -c '"status": "packed"' "$tmp/cluster/summary.json")" = 32 ] || fail "not every asset packed"
[ "$(($(wc -l <"$tmp/cluster/summary.csv") - 1))" = 32 ] || fail "the merged CSV does not list 32 assets"
for f in "$tmp"/local/*.packed.glb; do
  cmp -s "$f" "$tmp/cluster/$(basename "$f")" || fail "$(basename "$f") differs between the Slurm and the one-machine run"
done
[ "$(ls "$tmp"/cluster/*.packed.glb | wc -l)" = 32 ] || fail "the Slurm run wrote $(ls "$tmp"/cluster/*.packed.glb | wc -l) outputs"
echo "PASS: 32 assets as a 4-task Slurm array (job $array, merge $merge), byte-identical to one machine"
