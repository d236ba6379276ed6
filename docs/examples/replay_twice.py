"""Replay a recorded session twice (on one thread and on all) and compare the two: the same
state and the same render, pixel for pixel. With two builds' modules on PYTHONPATH in turn,
the same script compares builds. Usage: python3 replay_twice.py OUT_FOLDER [SESSION]"""
import os
import sys

import numpy as np

import impasto

out = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
session = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "..", "data", "strokes",
                                                             "demo.dat")
one = impasto.replay(session, threads=1)
many = impasto.replay(session)
difference = np.abs(one.render() - many.render())
print(f"state {one.state_hash:016x} / {many.state_hash:016x}, "
      f"largest pixel difference {difference.max():.6f}")
assert one.state_hash == many.state_hash and difference.max() == 0.0
one.save(os.path.join(out, "replayed.impasto"))
