#!/bin/sh
# Stands in for `candela run` in the runner's own tests; the scene argument picks a failure:
#   validation     exit 3, as the engine does on validation messages under "require"
#   content-error  an asset error on stderr, exit 0 (the engine renders what it could load)
case "$2" in
  validation) exit 3 ;;
  content-error)
    echo "candela: models/missing.glb: error: cannot open: No such file or directory" >&2
    exit 0 ;;
esac
echo "fake_engine.sh: unknown scene '$2'" >&2
exit 1
