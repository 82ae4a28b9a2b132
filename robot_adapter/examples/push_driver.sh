#!/bin/sh
# A relmap-robot exec driver: the target arrives as one JSON object on stdin, the
# answer leaves as one JSON object on stdout; anything for humans goes to stderr.
# This one only logs the target: put your arm's motion in the middle.
target=$(cat)
echo "push_driver.sh: target $target" >&2
# e.g.: python3 my_arm.py push "$target" || { echo '{"result":"failed"}'; exit 0; }
echo '{"result": "done", "message": "logged only, nothing moved"}'
