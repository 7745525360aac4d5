#!/usr/bin/env bash
# A single-node Slurm on this machine, for stack_sim_sweep's cluster test and
# for trying a sweep on Slurm (docs/sweeps.md, "A Slurm of your own").
#   start_slurm.sh [start|stop|status|env]
# start: writes a slurm.conf for this host (`hostname -s`, its CPUs) and a
#   munge key under the git-ignored .slurm/ (BRICK_SLURM_DIR overrides it),
#   starts munged, slurmctld and slurmd as plain daemons (no systemd needed)
#   on free ports, and waits until sinfo shows the node idle. A cluster of
#   this script already up is left as it is.
# stop: cancels the jobs on it and stops the three daemons by their pid files.
# status: sinfo and squeue of it. env: the line that points Slurm's commands
#   at it, for eval: eval "$(bash scripts/start_slurm.sh env)".
# Exit status: 0 done; 1 could not start (the logs' tails are printed);
# 3 Slurm or munge is not installed (bash scripts/install_deps.sh cluster).
set -uo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir="${BRICK_SLURM_DIR:-${repo_root}/.slurm}"
conf="${dir}/slurm.conf"
socket="${dir}/run/munge.socket.2"
export SLURM_CONF="${conf}"
export PATH="${PATH}:/usr/sbin:/sbin"
node="$(hostname -s 2>/dev/null || true)"
node="${node:-localhost}"

say() { echo "start_slurm.sh: $*" >&2; }

# The pid of a daemon of ours from its pid file, if it runs as that program;
# a pid file whose process is gone or is another program is stale: removed.
live_pid() {
  local file="${dir}/run/$1.pid" pid
  [[ -s "${file}" ]] || return 1
  pid="$(cat "${file}")"
  if [[ "${pid}" =~ ^[0-9]+$ ]] && [[ "$(cat "/proc/${pid}/comm" 2>/dev/null)" == "$1"* ]]; then
    echo "${pid}"
    return 0
  fi
  rm -f "${file}"
  return 1
}

# A TCP port from $1 on that nothing listens on (IPv4 or IPv6).
free_port() {
  local port=$1 local_address state table
  local -A used=()
  for table in /proc/net/tcp /proc/net/tcp6; do
    [[ -r "${table}" ]] || continue
    while read -r _ local_address _ state _; do
      [[ "${state}" == 0A ]] && used[$((16#${local_address##*:}))]=1
    done < <(tail -n +2 "${table}")
  done
  while [[ -n "${used[${port}]:-}" ]]; do port=$((port + 1)); done
  echo "${port}"
}

stop_daemon() {
  local name=$1 pid
  pid="$(live_pid "${name}")" || return 0
  kill "${pid}" 2>/dev/null
  for _ in $(seq 50); do
    kill -0 "${pid}" 2>/dev/null || break
    sleep 0.2
  done
  if kill -0 "${pid}" 2>/dev/null; then
    say "${name} (pid ${pid}) did not stop; killing it"
    kill -9 "${pid}" 2>/dev/null
  fi
  rm -f "${dir}/run/${name}.pid"
}

node_state() { sinfo -h -n "${node}" -o %T 2>/dev/null | head -1; }

show_logs() {
  for log in "${dir}/log/munged.log" "${dir}/log/slurmctld.log" "${dir}/log/slurmd.log"; do
    [[ -s "${log}" ]] && { echo "--- ${log}" >&2; tail -n 8 "${log}" >&2; }
  done
}

write_conf() {
  local ctld_port d_port cpus
  ctld_port="$(free_port 6817)"
  d_port="$(free_port $((ctld_port + 1)))"
  cpus="$(nproc)"
  cat >"${conf}" <<EOF
# Written by scripts/start_slurm.sh: one node, this host, every job as root.
ClusterName=brickstack
SlurmctldHost=${node}(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=${ctld_port}
SlurmdPort=${d_port}
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=${socket}
StateSaveLocation=${dir}/state/slurmctld
SlurmdSpoolDir=${dir}/state/slurmd
SlurmctldPidFile=${dir}/run/slurmctld.pid
SlurmdPidFile=${dir}/run/slurmd.pid
SlurmctldLogFile=${dir}/log/slurmctld.log
SlurmdLogFile=${dir}/log/slurmd.log
# No cgroups in a container: track processes by their parent, bind nothing.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
# Schedule every second, not every minute, and start batch jobs at once:
# a sweep's tasks are short.
SchedulerParameters=batch_sched_delay=0,sched_interval=1,sched_min_interval=100000
ReturnToService=2
MpiDefault=none
SwitchType=switch/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MaxArraySize=1000001
MaxJobCount=1000000
NodeName=${node} NodeAddr=127.0.0.1 CPUs=${cpus} State=UNKNOWN
PartitionName=local Nodes=${node} Default=YES MaxTime=INFINITE State=UP
EOF
}

start_munge() {
  if live_pid munged >/dev/null; then return 0; fi
  rm -f "${socket}" "${socket}.lock"
  if [[ ! -s "${dir}/munge/munge.key" ]]; then
    mungekey --create --keyfile="${dir}/munge/munge.key" 2>/dev/null \
      || dd if=/dev/urandom of="${dir}/munge/munge.key" bs=1024 count=1 status=none
  fi
  chmod 0400 "${dir}/munge/munge.key"
  munged --socket="${socket}" --key-file="${dir}/munge/munge.key" \
    --pid-file="${dir}/run/munged.pid" --log-file="${dir}/log/munged.log" \
    --seed-file="${dir}/munge/munged.seed"
}

start() {
  for program in munged slurmctld slurmd sinfo sbatch squeue scontrol; do
    if ! command -v "${program}" >/dev/null; then
      say "${program} is not installed" \
        "(bash scripts/install_deps.sh cluster installs Slurm and munge)"
      exit 3
    fi
  done
  local ctld d
  ctld="$(live_pid slurmctld)" && d="$(live_pid slurmd)" && live_pid munged >/dev/null \
    && [[ "$(node_state)" == idle* || "$(node_state)" == mix* || "$(node_state)" == alloc* ]] && {
      say "already up (slurmctld ${ctld}, slurmd ${d}); ${conf}"
      echo "export SLURM_CONF=${conf}"
      return 0
    }
  # Whatever half of a cluster is left over goes; then a clean start.
  stop_daemon slurmd
  stop_daemon slurmctld
  mkdir -p "${dir}/munge" "${dir}/run" "${dir}/log" "${dir}/state/slurmctld" "${dir}/state/slurmd"
  # munged wants its key folder private, and every folder up to its socket
  # open to all (execute permission).
  chmod 0700 "${dir}/munge"
  chmod 0755 "${dir}" "${dir}/run"
  if ! start_munge; then say "munged did not start"; show_logs; exit 1; fi
  write_conf
  # -c: no jobs or node states from an earlier start.
  if ! slurmctld -c -f "${conf}"; then say "slurmctld did not start"; show_logs; exit 1; fi
  if ! slurmd -c -f "${conf}" -N "${node}"; then say "slurmd did not start"; show_logs; exit 1; fi
  local state=""
  for _ in $(seq 120); do
    state="$(node_state)"
    [[ "${state}" == idle* ]] && break
    if [[ "${state}" == drain* || "${state}" == down* ]]; then
      scontrol update nodename="${node}" state=resume >/dev/null 2>&1
    fi
    sleep 0.5
  done
  if [[ "${state}" != idle* ]]; then
    say "the node is '${state:-not listed}' after 60 s, not idle"
    show_logs
    stop
    exit 1
  fi
  say "up: node ${node}, $(nproc) CPUs, partition local; ${conf}"
  echo "export SLURM_CONF=${conf}"
}

stop() {
  if live_pid slurmctld >/dev/null; then
    jobs="$(squeue -h -o %A 2>/dev/null | sort -u | tr '\n' ' ')"
    # shellcheck disable=SC2086
    if [[ -n "${jobs// /}" ]]; then
      scancel ${jobs} 2>/dev/null
      for _ in $(seq 20); do
        [[ -z "$(squeue -h -o %A 2>/dev/null)" ]] && break
        sleep 0.5
      done
    fi
  fi
  stop_daemon slurmd
  stop_daemon slurmctld
  stop_daemon munged
  rm -f "${socket}" "${socket}.lock"
}

case "${1:-start}" in
  start) start ;;
  stop) stop; say "stopped" ;;
  status)
    live_pid slurmctld >/dev/null || { say "not running"; exit 1; }
    sinfo && squeue ;;
  env) echo "export SLURM_CONF=${conf}" ;;
  *) say "unknown command '$1' (start, stop, status or env)"; exit 2 ;;
esac
