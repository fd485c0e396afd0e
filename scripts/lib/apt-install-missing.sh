#!/usr/bin/env bash
# apt-install-missing.sh PACKAGE... [PACKAGE-]...: installs those of the Debian packages that are not
# installed yet; a name with a trailing '-' is removed in the same apt run if it is installed (apt cannot
# resolve a Conflicts on its own). Works as root or through sudo; does nothing (and needs no network)
# when there is nothing to do.
set -euo pipefail
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
missing=()
for p in "$@"; do
  if [[ "$p" == *- ]]; then
    installed "${p%-}" && missing+=("$p")
  else
    installed "$p" || missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "lucent: installing ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then sudo=(); elif command -v sudo >/dev/null; then sudo=(sudo); else
  echo "lucent: missing packages (${missing[*]}) and neither root nor sudo: install them, then rerun" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
