#!/usr/bin/env bash
# The ROS tests of vehicle-ros (ros/README.md, "Tests"): a real rosmaster, the node on
# ros/tests/worlds/ros.toml, an independent rospy client (ros/tests/client.py) that calls the
# services and reads the topics, then the master stopped under the node, which must exit 0;
# then, on a master of its own, the node on ros/tests/worlds/two_cars.toml serving two cars,
# each driven differently by the client.
#
#   ros/tests/run.sh            # builds target/ros-venv: pip install ./python ./ros
#
# Needs Debian's ROS 1 packages (.ci/run installs them): python3-rospy python3-rosmaster
# python3-rostopic python3-rosservice python3-genpy ros-std-msgs python3-sensor-msgs.
# VEHICLE_ROS_VENV=DIR uses (or makes) that virtual environment instead;
# VEHICLE_ROS_SKIP_PYTHON_INSTALL=1 keeps the webots-vehicle already in it (maturin develop).
set -euo pipefail
cd "$(dirname "$0")/../.."

VENV=${VEHICLE_ROS_VENV:-target/ros-venv}
LOGS=target/ros-tests
mkdir -p "$LOGS"

# rospy and the message packages are the distribution's, for its /usr/bin/python3: the venv
# sees them through --system-site-packages.
if [ ! -x "$VENV/bin/python" ]; then
  /usr/bin/python3 -m venv --system-site-packages "$VENV"
fi
if [ "${VEHICLE_ROS_SKIP_PYTHON_INSTALL:-0}" != 1 ]; then
  SECONDS=0
  "$VENV/bin/pip" install --quiet ./python
  echo "pip install ./python took ${SECONDS} s"
fi
"$VENV/bin/pip" install --quiet ./ros

# The committed message classes are genpy's output for the committed definitions.
GENERATED=$(mktemp -d)
MASTER_PID=""
NODE_PID=""
cleanup() {
  if [ -n "$NODE_PID" ]; then kill "$NODE_PID" 2>/dev/null || true; fi
  if [ -n "$MASTER_PID" ]; then kill "$MASTER_PID" 2>/dev/null || true; fi
  rm -rf "$GENERATED"
}
trap cleanup EXIT
/usr/bin/python3 ros/generate.py "$GENERATED"
diff -r -x '*.msg' -x '*.srv' -x __pycache__ "$GENERATED/webots_ros" ros/webots_ros
echo "ok   ros/webots_ros's classes are genpy's output for its definitions"

free_port() { /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
PORT=$(free_port)
export ROS_MASTER_URI="http://127.0.0.1:$PORT"
export ROS_HOSTNAME=127.0.0.1
export ROS_LOG_DIR="$PWD/$LOGS/ros-log"
unset ROS_NAMESPACE

# No master: the node says so and fails (Webots: ROS_FATAL, exit).
set +e
"$VENV/bin/vehicle-ros" --world ros/tests/worlds/ros.toml >"$LOGS/no-master.log" 2>&1
status=$?
set -e
if [ "$status" -ne 1 ] || ! grep -q "no ROS master at $ROS_MASTER_URI" "$LOGS/no-master.log"; then
  echo "FAIL vehicle-ros without a master: status $status" >&2
  cat "$LOGS/no-master.log" >&2
  exit 1
fi
echo "ok   without a master vehicle-ros exits 1 naming the URI"

rosmaster --core -p "$PORT" >"$LOGS/master.log" 2>&1 &
MASTER_PID=$!
for _ in $(seq 100); do
  if /usr/bin/python3 -c 'import rosgraph, sys; sys.exit(0 if rosgraph.is_master_online() else 1)'; then break; fi
  sleep 0.1
done

"$VENV/bin/vehicle-ros" --world ros/tests/worlds/ros.toml >"$LOGS/node.log" 2>&1 &
NODE_PID=$!

SECONDS=0
if ! VEHICLE_ROS_NODE_PID=$NODE_PID "$VENV/bin/python" ros/tests/client.py; then
  echo "--- node log (last 40 lines) ---" >&2
  tail -n 40 "$LOGS/node.log" >&2
  exit 1
fi
echo "the client's checks took ${SECONDS} s"

# The node's stderr carries the C API's own warning text for the refused NaN steering angle.
if ! grep -q "steering" "$LOGS/node.log"; then
  echo "FAIL the node's stderr lacks Webots' steering warning" >&2
  exit 1
fi
echo "ok   the node's stderr has the C API's warnings"

# Webots' prefix rule: a second car's node with --name ego serves everything under /ego/,
# beside the first node's root names; Ctrl-C (SIGINT) ends it with status 0.
"$VENV/bin/vehicle-ros" --world ros/tests/worlds/ros.toml --name ego >"$LOGS/node-ego.log" 2>&1 &
EGO_PID=$!
"$VENV/bin/python" - <<'PY'
import rosgraph, rospy, sys
rospy.init_node("prefix_check")
rospy.wait_for_service("/ego/robot/get_device_list", timeout=30)  # the last one advertised
master = rosgraph.Master("/prefix_check")
services = {name for name, _ in master.getSystemState()[2]}
topics = {name for name, _ in master.getTopicTypes()}
wanted = ["/ego/automobile/set_gear", "/ego/gps/enable", "/ego/robot/get_time", "/automobile/set_gear"]
missing = [n for n in wanted if n not in services]
missing += [n for n in ["/ego/automobile/current_speed", "/automobile/current_speed"] if n not in topics]
providers = dict(master.getSystemState()[2])
if providers.get("/ego/automobile/set_gear") != ["/ego"]:
    missing.append("/ego/automobile/set_gear served by the node /ego")
if missing:
    sys.exit(f"FAIL the --name ego node lacks {missing}")
print("ok   --name ego serves /ego/automobile/..., /ego/<device>/..., beside /automobile/...")
PY
kill -INT "$EGO_PID"
set +e
wait "$EGO_PID"
status=$?
set -e
if [ "$status" -ne 0 ] || ! grep -q "interrupted" "$LOGS/node-ego.log"; then
  echo "FAIL vehicle-ros --name ego after SIGINT: status $status" >&2
  tail -n 20 "$LOGS/node-ego.log" >&2
  exit 1
fi
echo "ok   vehicle-ros exits 0 on SIGINT"

# The master goes away: the node notices within its check period and exits 0.
kill "$MASTER_PID"
wait "$MASTER_PID" 2>/dev/null || true
MASTER_PID=""
for _ in $(seq 150); do
  if ! kill -0 "$NODE_PID" 2>/dev/null; then break; fi
  sleep 0.1
done
if kill -0 "$NODE_PID" 2>/dev/null; then
  echo "FAIL vehicle-ros still runs 15 s after the master went away" >&2
  exit 1
fi
set +e
wait "$NODE_PID"
status=$?
set -e
NODE_PID=""
if [ "$status" -ne 0 ] || ! grep -q "the master went away" "$LOGS/node.log"; then
  echo "FAIL vehicle-ros after the master went away: status $status" >&2
  tail -n 20 "$LOGS/node.log" >&2
  exit 1
fi
echo "ok   vehicle-ros exits 0 when the master goes away"

# Several cars (ros/README.md, "Several cars"): a master of its own, the node on the two-car
# world serving each car without a programme under /<car>/, the client driving both.
PORT=$(free_port)
export ROS_MASTER_URI="http://127.0.0.1:$PORT"
rosmaster --core -p "$PORT" >"$LOGS/master-two-cars.log" 2>&1 &
MASTER_PID=$!
for _ in $(seq 100); do
  if /usr/bin/python3 -c 'import rosgraph, sys; sys.exit(0 if rosgraph.is_master_online() else 1)'; then break; fi
  sleep 0.1
done
refused() {  # refused EXPECTED-TEXT ARGUMENTS...: the node exits 1 saying EXPECTED-TEXT
  local expected=$1
  shift
  set +e
  "$VENV/bin/vehicle-ros" --world ros/tests/worlds/two_cars.toml "$@" >"$LOGS/refused.log" 2>&1
  local status=$?
  set -e
  if [ "$status" -ne 1 ] || ! grep -qF -- "$expected" "$LOGS/refused.log"; then
    echo "FAIL vehicle-ros $*: status $status" >&2
    cat "$LOGS/refused.log" >&2
    exit 1
  fi
  echo "ok   vehicle-ros $* exits 1: $expected"
}
refused "--name names one car's node" --name ego
refused "--cars names 'delta', which is no car of the world (its cars: alpha, beta, gamma)" --cars delta
refused "--cars names 'alpha' twice" --cars alpha,alpha

"$VENV/bin/vehicle-ros" --world ros/tests/worlds/two_cars.toml >"$LOGS/node-two-cars.log" 2>&1 &
NODE_PID=$!
if ! VEHICLE_ROS_NODE_PID=$NODE_PID "$VENV/bin/python" ros/tests/client.py two-cars; then
  echo "--- two-car node log (last 40 lines) ---" >&2
  tail -n 40 "$LOGS/node-two-cars.log" >&2
  exit 1
fi
kill -INT "$NODE_PID"
set +e
wait "$NODE_PID"
status=$?
set -e
NODE_PID=""
if [ "$status" -ne 0 ]; then
  echo "FAIL the two-car node after SIGINT: status $status" >&2
  tail -n 20 "$LOGS/node-two-cars.log" >&2
  exit 1
fi
echo "ok   the two-car node exits 0 on SIGINT"
echo "ROS tests passed"
