#!/usr/bin/env bash
# Install Debian's headless Chromium (the viewer's browser test and screenshots) if absent.
# Called by `make setup`; needs root or sudo for apt-get. Skip with ROBOCRAM_NO_CHROMIUM=1.
set -euo pipefail
if [ "${ROBOCRAM_NO_CHROMIUM:-0}" = "1" ] || command -v chromium >/dev/null 2>&1; then
    exit 0
fi
if [ "$(id -u)" -eq 0 ]; then
    SUDO=""
elif command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
else
    echo "setup_chromium: chromium is missing and apt-get needs root; run: apt-get install -y chromium" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq chromium >/dev/null
command -v chromium >/dev/null
