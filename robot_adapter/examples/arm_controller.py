#!/usr/bin/env python3
"""A relmap-robot tcp_json controller: one target (JSON) per line in, one result (JSON)
per line out. This one only logs the target; put your arm's motion in push()."""
import json
import socketserver
import sys


def push(target):
    print("arm_controller.py: target", json.dumps(target), file=sys.stderr, flush=True)
    return {"result": "done", "message": "logged only, nothing moved"}


class Arm(socketserver.StreamRequestHandler):
    def handle(self):
        for line in self.rfile:
            self.wfile.write((json.dumps(push(json.loads(line))) + "\n").encode())


port = int(sys.argv[1]) if len(sys.argv) > 1 else 7000
socketserver.TCPServer(("127.0.0.1", port), Arm).serve_forever()
