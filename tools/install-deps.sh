#!/usr/bin/env bash
# Installs what tioa-check needs from Debian's packages (as root). Quiet when all is there.
set -euo pipefail
packages=(g++ cmake ninja-build python3
          libboost-graph-dev libboost-dev libeigen3-dev catch2 libfmt-dev libcli11-dev
          nlohmann-json3-dev
          # BuDDy: the symbolic checks (checker/symbolic_space.hpp)
          libbdd-dev
          # distributed exploration under mpirun (issue 18, cli/mpi_run.hpp; the build
          # leaves it out and tests/cli/mpi_same.py is skipped without them)
          openmpi-bin libopenmpi-dev
          # the JSON reports against docs/report.schema.json (tests/cli/validate_reports.py;
          # skipped without it)
          python3-jsonschema
          # the headless test of the --html pages (tests/cli/html_tests.cmake; skipped
          # without it). Measured on a Debian 12 CI machine: 130 packages, 137 MB
          # download, 609 MB on disk, 89 s to install.
          chromium)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
fi
