#!/usr/bin/env bash
# One command for a new user: install what is missing, build, and open voxmod on a bundled model.
# Any arguments replace the default model (e.g. scripts/run.sh part.stl).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
if (($# == 0)); then set -- models/featuretype.stl; fi
exec ./build/voxmod "$@"
