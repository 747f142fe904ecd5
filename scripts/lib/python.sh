# Sourced by the project's scripts: find_python MODULE... sets PYTHON to a Python 3 that imports every
# MODULE, looking where a user's machine has one:
#   1. $CELLSIM_PYTHON, if set (and then only it: a choice the user made must not be overridden);
#   2. Debian's /usr/bin/python3, where `scripts/setup` installs the packages;
#   3. every other python3 on PATH, in PATH order (a pyenv or conda python3 often comes first but
#      cannot import Debian's packages; one that can is as good).
# Without one it prints what is missing and how to get it, and returns 1.
find_python() {
  local candidates=() candidate tried=()
  if [[ -n "${CELLSIM_PYTHON:-}" ]]; then
    candidates=("$CELLSIM_PYTHON")
  else
    candidates=(/usr/bin/python3)
    while IFS= read -r candidate; do candidates+=("$candidate"); done < <(type -ap python3 2>/dev/null)
  fi
  for candidate in "${candidates[@]}"; do
    [[ -x "$candidate" ]] || continue
    tried+=("$candidate")
    if "$candidate" -c 'import importlib, sys
for name in sys.argv[1:]: importlib.import_module(name)' "$@" 2>/dev/null; then
      PYTHON=$candidate
      return 0
    fi
  done
  {
    echo "error: no Python 3 here imports all of: $*"
    echo "  tried: ${tried[*]:-no python3 found${CELLSIM_PYTHON:+ (CELLSIM_PYTHON=$CELLSIM_PYTHON)}}"
    echo "  install the packages with scripts/setup (Debian), or point CELLSIM_PYTHON at a python3 that has them"
  } >&2
  return 1
}
