# Sourced by the other scripts: the environment every build, demo and test runs in.
# Debian's ROS 1 lives under /usr and its Python modules only on /usr/bin/python3, so
# /usr/bin goes first on PATH (a pyenv python3 there cannot see them), then the venv
# (made with --system-site-packages) that holds the PyPI extras such as xacro 1.13.
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export ROOT
export PATH="$ROOT/.venv/bin:/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
export ROS_PYTHON_VERSION=3
if [ -f "$ROOT/devel/setup.bash" ]; then
  # setup.bash reads unset variables; relax -u while it runs.
  case $- in *u*) set +u; . "$ROOT/devel/setup.bash"; set -u ;; *) . "$ROOT/devel/setup.bash" ;; esac
fi
