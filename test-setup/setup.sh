#!/usr/bin/env bash
# test-setup/setup.sh - gets the test peers the suite talks to, before ./antw runs the tests or a benchmark.
#
# The peers are declared beside this script:
#   debian-packages.txt  Debian packages (socat, mbpoll, Xvfb, ...), one per line
#   requirements.txt     Python packages, installed into a virtual environment this build owns
#   package.json         npm packages, installed into a folder this build owns
# What can be installed is installed (Debian packages need root or password-less sudo); what cannot is named on
# one line with the command that installs it, and the tests that need it skip themselves with the same words.
#
# Output: on stdout, Ant options (one per line) telling the tests where the peers are:
#   -Drwe.test.python=PATH         a Python interpreter with requirements.txt installed
#   -Drwe.test.node_modules=PATH   the folder holding package.json's packages
# Progress and problems go to stderr. Never fails the build: a missing peer skips tests, it does not fail them.
# Set RWE_TEST_SETUP=off to skip all of this (the tests then use whatever the machine has).
set -uo pipefail

here=$(cd "$(dirname "$0")" && pwd)
cache="${XDG_CACHE_HOME:-$HOME/.cache}/robotworld/test-peers"

say() { echo "test-setup: $*" >&2; }

[ "${RWE_TEST_SETUP:-on}" = off ] && exit 0

# --- which Debian packages are wanted -------------------------------------------------------------------
wanted_packages() {
  sed -e 's/#.*//' -e 's/[[:space:]]//g' "$here/debian-packages.txt" 2>/dev/null | grep -v '^$'
}

has_content() { [ -f "$1" ] && grep -q '[^[:space:]]' <(sed 's/#.*//' "$1"); }

python_wanted=false
has_content "$here/requirements.txt" && python_wanted=true
node_wanted=false
[ -f "$here/package.json" ] && node_wanted=true

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q 'install ok installed'; }

missing=()
if command -v dpkg-query >/dev/null 2>&1; then
  for package in $(wanted_packages); do
    installed "$package" || missing+=("$package")
  done
  # a headless JRE cannot open windows (no libawt_xawt): the GUI tests need the full JRE of the same package
  java_bin=$(readlink -f "$(command -v java)" 2>/dev/null || true)
  if [ -n "$java_bin" ] && [ ! -e "$(dirname "$(dirname "$java_bin")")/lib/libawt_xawt.so" ]; then
    jre_package=$(dpkg -S "$java_bin" 2>/dev/null | cut -d: -f1 | sed 's/-headless$//')
    [ -n "$jre_package" ] && ! installed "$jre_package" && missing+=("$jre_package")
  fi
  if $python_wanted && ! { command -v python3 >/dev/null 2>&1 && python3 -c 'import venv, ensurepip' 2>/dev/null; }; then
    installed python3-venv || missing+=(python3-venv)
  fi
  if $node_wanted && ! command -v npm >/dev/null 2>&1; then
    installed npm || missing+=(nodejs npm)
  fi
else
  say "not a Debian-like machine (no dpkg-query): using the test peers that are on the PATH"
fi

may_install() {
  command -v apt-get >/dev/null 2>&1 || return 1
  [ "$(id -u)" -eq 0 ] && { sudo=""; return 0; }
  command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null && { sudo="sudo -n"; return 0; }
  return 1
}

if [ ${#missing[@]} -gt 0 ]; then
  if may_install; then
    say "installing ${missing[*]} from Debian's packages"
    export DEBIAN_FRONTEND=noninteractive
    apt_options=(-y -qq --no-install-recommends -o DPkg::Lock::Timeout=300)
    # a fresh machine may have no package lists yet: update only when the first try fails
    $sudo apt-get install "${apt_options[@]}" "${missing[@]}" >/dev/null 2>&1 || {
      $sudo apt-get update -qq -o DPkg::Lock::Timeout=300 >/dev/null 2>&1
      $sudo apt-get install "${apt_options[@]}" "${missing[@]}" >/dev/null 2>&1
    } || say "could not install ${missing[*]}; the tests that need them will be skipped" \
          "(install: sudo apt-get install ${missing[*]})"
  else
    say "missing ${missing[*]} and not allowed to install (not root, no password-less sudo):" \
        "the tests that need them will be skipped (install: sudo apt-get install ${missing[*]})"
  fi
fi

# --- Python peers: a virtual environment per set of requirements ----------------------------------------
if $python_wanted; then
  digest=$(sha256sum "$here/requirements.txt" | cut -c1-12)
  venv="$cache/python-$digest"
  if [ ! -e "$venv/.complete" ]; then
    if command -v python3 >/dev/null 2>&1; then
      say "installing the Python test peers ($(sed 's/#.*//' "$here/requirements.txt" | xargs)) into $venv"
      rm -rf "$venv"
      mkdir -p "$cache"
      if python3 -m venv "$venv" >/dev/null 2>&1 \
          && "$venv/bin/python" -m pip install -q --disable-pip-version-check -r "$here/requirements.txt" >&2; then
        touch "$venv/.complete"
      else
        say "could not install the Python test peers; the tests that need them will be skipped"
        rm -rf "$venv"
      fi
    else
      say "no python3: the tests that need Python peers will be skipped (install: sudo apt-get install python3-venv)"
    fi
  fi
  [ -e "$venv/.complete" ] && echo "-Drwe.test.python=$venv/bin/python"
fi

# --- npm peers: a folder per package.json ----------------------------------------------------------------
if $node_wanted; then
  digest=$(sha256sum "$here/package.json" | cut -c1-12)
  folder="$cache/node-$digest"
  if [ ! -e "$folder/.complete" ]; then
    if command -v npm >/dev/null 2>&1; then
      say "installing the npm test peers into $folder"
      rm -rf "$folder"
      mkdir -p "$folder"
      cp "$here/package.json" "$folder/"
      if (cd "$folder" && npm install --no-audit --no-fund --silent >&2); then
        touch "$folder/.complete"
      else
        say "could not install the npm test peers; the tests that need them will be skipped"
        rm -rf "$folder"
      fi
    else
      say "no npm: the tests that need npm peers will be skipped (install: sudo apt-get install nodejs npm)"
    fi
  fi
  [ -e "$folder/.complete" ] && echo "-Drwe.test.node_modules=$folder/node_modules"
fi
exit 0
