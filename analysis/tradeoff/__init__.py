"""The speed-accuracy sweep (docs/studies/tradeoff.md), run from the repository's top folder as

    /usr/bin/python3 -m analysis.tradeoff --build build/release --out out/tradeoff [--full] [--jobs N]

__main__ (command line, parallel runs), points (the sweeps), run (one point: scene, launch, reading
the driver's output), launch (the small process that times a driver and reads its peak memory,
run by path), table (the CSV, resume), pareto (front and cheapest per target, pure functions),
report (the text), plot (the PNG).
"""
