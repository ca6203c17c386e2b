#!/usr/bin/env python3
"""A controller process that fails on purpose, for tests/command/CommandControllerTest.cpp:
faulty_controller.py FAULT [TICK]. It answers like the protocol asks (the plan's feed-forward)
until tick TICK (default 5), then: `exit` exits with status 3 after a line on stderr, `nan`
answers "nan nan", `range` answers beyond any wheel's limit, `garbage` answers text, `long`
answers a line of 5000 bytes, `hang` stops answering (and ignores the end of its input),
`twice` answers two lines, `close` closes its standard output and keeps running. `notready`
answers the reset with something else than "ready"; `slowstart` never answers it."""

import json
import os
import sys
import time

fault = sys.argv[1]
at = int(sys.argv[2]) if len(sys.argv) > 2 else 5


def say(text):
    sys.stdout.write(text + "\n")
    sys.stdout.flush()


for line in iter(sys.stdin.readline, ""):
    kind, _, rest = line.partition(" ")
    if kind == "reset":
        fields = json.loads(rest)["tick_fields"]
        if fault == "notready":
            say("hello")
        elif fault == "slowstart":
            time.sleep(3600)
        else:
            say("ready")
        continue
    tick = dict(zip(fields, map(float, rest.split())))
    if tick["tick"] < at:
        say("%r %r" % (tick["ff_left_radps"], tick["ff_right_radps"]))
        continue
    if fault == "exit":
        sys.stderr.write("controller gave up at tick %d\n" % tick["tick"])
        sys.exit(3)
    elif fault == "nan":
        say("nan nan")
    elif fault == "range":
        say("1e6 0")
    elif fault == "garbage":
        say("left is fast")
    elif fault == "long":
        say("1" * 5000)
    elif fault == "twice":
        say("0 0")
        say("0 0")
    elif fault == "close":
        os.close(1)
        time.sleep(3600)
    elif fault == "hang":
        while True:
            time.sleep(3600)
