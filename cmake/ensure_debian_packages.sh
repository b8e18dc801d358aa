# Sourced by examples/run_demo.sh and tests/run_all.sh (and .ci/run):
#   ensure_debian_packages <caller name> <package>...
# On Debian/Ubuntu, installs with apt-get whichever of the packages are missing when run
# as root (nothing happens when all are present); otherwise says what is missing and
# carries on, since they may be installed outside dpkg.
ensure_debian_packages() {
  local who="$1"
  shift
  if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "$who: not a Debian system; make sure these are installed: $*" >&2
    return 0
  fi
  local missing=() p
  for p in "$@"; do
    if [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)" != "install ok installed" ]]; then
      missing+=("$p")
    fi
  done
  ((${#missing[@]} == 0)) && return 0
  if [[ "$(id -u)" == 0 ]]; then
    echo "$who: installing ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update
    apt-get install -y --no-install-recommends "${missing[@]}"
  else
    echo "$who: missing packages: ${missing[*]}" >&2
    echo "$who: install them with: sudo apt-get install ${missing[*]}" >&2
    echo "$who: trying anyway (they may be installed outside dpkg)" >&2
  fi
}
