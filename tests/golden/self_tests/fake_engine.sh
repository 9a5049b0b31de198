#!/bin/sh
# Stands in for `candela run` in the runner's own tests: exits as the engine does when
# validation messages appear under CANDELA_VALIDATION=require.
exit 3
