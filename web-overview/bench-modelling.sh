#!/usr/bin/env bash
# Prints the modelling mode's figures for a 10,000-point plant in headless Chromium (see ModellingBenchmark).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
KTCS_BENCH=modelling ./mvnw -B verify -pl web-overview -am -Dtest=ModellingBenchmark \
    -Dsurefire.failIfNoSpecifiedTests=false -Dspotless.check.skip=true | grep -E '^modelling_|Tests run:|FAIL'
