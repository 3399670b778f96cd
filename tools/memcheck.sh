#!/usr/bin/env bash
# Leak and memory-error check of the C++ test under valgrind (slow: a few minutes on llvmpipe).
# Reports "definitely lost" blocks; those inside Mesa's driver (frames shown as ???) and glibc's
# loader reads are not ours.
set -euo pipefail
cd "$(dirname "$0")/.."
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" valgrind --leak-check=full --show-leak-kinds=definite \
  build/bin/TestLightShaftPass tests/baselines/TestLightShaftPass.png 2>&1 |
  tee build/memcheck.log | grep -E "definitely lost|ERROR SUMMARY|mean absolute"
