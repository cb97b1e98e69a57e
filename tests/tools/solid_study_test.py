#!/usr/bin/python3
"""The solid study (issue 48, docs/studies/geometry.md) as a user runs it:

- the inclined Lamb problem (data/scenes/lamb2d_inclined.toml) at dx = 0.0625: the cut-cell Galerkin
  errors at centre, receiver and buried within 1.5 times the axis-aligned half-plane's
  (data/scenes/lamb2d_halfplane.toml) and below the staircase's at the receiver; at dx = 0.25 RK
  collocation's, the UL-SPH's and the TL-SPH's likewise within 1.5 times, and under bounds near their measured errors;
- materials by region refused by name for RK collocation, a moment tensor likewise, a crack and a
  fixed surface for the very weak SPH; a fixed surface ([[surface_boundary]]) holds a rigid inclusion
  still by RK collocation, the UL- and TL-SPH; the UL-SPH's cracks: one through the box stops the receiver, one to depth 2.5 blocks
  most of the Rayleigh pulse;
- bad geometry refused before any work with exit 2 naming the key: a shape outside the box, an
  empty solid, overlapping regions without a rule, an open surface mesh, a load on an unknown
  surface, a probe outside the solid.

    /usr/bin/python3 tests/tools/solid_study_test.py --solid BUILD/drivers/solid --scenes data/scenes
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile


def run(command):
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return done.returncode, done.stdout


def errors(folder, case):
    with open(os.path.join(folder, "cases.csv")) as f:
        for row in csv.DictReader(f):
            if row["case"] == case:
                return {p: float(row[p + "_relative_l2"]) for p in ("centre", "receiver", "buried")}
    raise SystemExit("no case " + case + " in " + folder)


OPEN_STL = """solid open
facet normal 0 0 -1
 outer loop
  vertex 0 0 0
  vertex 1 0 0
  vertex 0 1 0
 endloop
endfacet
facet normal 0 -1 0
 outer loop
  vertex 0 0 0
  vertex 0 0 1
  vertex 1 0 0
 endloop
endfacet
endsolid open
"""

BLOCK = """[scene]
name = "bad"
dimension = 3
[geometry]
shape = "block"
lower = [-1.0, -1.0, -1.0]
upper = [1.0, 1.0, 1.0]
spacing = 0.25
solid = "part"
[[shape]]
name = "part"
type = "mesh"
file = "open.stl"
[material]
density = 1.0
lambda = 1.0
mu = 1.0
[method]
name = "very_weak_sph"
[[load]]
type = "point_force"
position = [0.0, 0.0, 0.0]
direction = [0.0, 0.0, 1.0]
time_function = { type = "ricker", peak_frequency = 1.0 }
[integrator]
end_time = 1.0
"""


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--solid", required=True)
    parser.add_argument("--scenes", required=True)
    args = parser.parse_args()
    failures = []
    with tempfile.TemporaryDirectory() as work:
        runs = {}
        for name in ("lamb2d_inclined", "lamb2d_halfplane"):
            out = os.path.join(work, name)
            code, text = run([args.solid, "--scene", os.path.join(args.scenes, name + ".toml"), "--out", out, "--quiet",
                              "--set", "study.spacings=[0.0625]", "--set", 'study.methods=["very_weak_sph"]'])
            if code != 0:
                print(text)
                sys.exit(name + ": exit " + str(code))
            runs[name] = out
        inclined = errors(runs["lamb2d_inclined"], "cut_0.0625")
        staircase = errors(runs["lamb2d_inclined"], "staircase_0.0625")
        aligned = errors(runs["lamb2d_halfplane"], "cut_0.0625")
        for probe in ("centre", "receiver", "buried"):
            ratio = inclined[probe] / aligned[probe]
            print("%-8s inclined cut %.4f, staircase %.4f, axis-aligned %.4f: %.2f times" %
                  (probe, inclined[probe], staircase[probe], aligned[probe], ratio))
            if ratio > 1.5:
                failures.append("%s: the inclined error is %.2f times the axis-aligned (target 1.5)" % (probe, ratio))
        if not inclined["receiver"] < staircase["receiver"]:
            failures.append("the cut cells do not beat the staircase at the receiver")

        # RK collocation (lattice nodes inside, surface nodes with traction rows), the UL-SPH and the
        # TL-SPH (a body-fitted fill) on the same two solids at dx = 0.25; measured inclined / aligned:
        # RK 0.155 / 0.249 / 0.192 and 0.154 / 0.384 / 0.138, UL-SPH 0.542 / 0.811 / 0.350 and
        # 0.482 / 0.793 / 0.319, TL-SPH 0.456 / 0.567 / 0.184 and 0.333 / 0.580 / 0.206 (centre /
        # receiver / buried)
        others = {"reproducing_kernel": ("rk_0.25", {"centre": 0.17, "receiver": 0.27, "buried": 0.21}),
                  "updated_lagrangian_sph": ("ulsph_0.25", {"centre": 0.6, "receiver": 0.9, "buried": 0.39}),
                  "total_lagrangian_sph": ("tlsph_0.25", {"centre": 0.5, "receiver": 0.62, "buried": 0.21})}
        for method, (case, bounds) in others.items():
            scored = {}
            for name in ("lamb2d_inclined", "lamb2d_halfplane"):
                out = os.path.join(work, name + "-" + method)
                code, text = run([args.solid, "--scene", os.path.join(args.scenes, name + ".toml"), "--out", out,
                                  "--quiet", "--set", "study.spacings=[0.25]", "--set", 'study.methods=["%s"]' % method])
                if code != 0:
                    print(text)
                    sys.exit(name + " by " + method + ": exit " + str(code))
                scored[name] = errors(out, case)
            for probe in ("centre", "receiver", "buried"):
                tilted, aligned_error = scored["lamb2d_inclined"][probe], scored["lamb2d_halfplane"][probe]
                ratio = tilted / aligned_error
                print("%-8s %s inclined %.4f, axis-aligned %.4f: %.2f times" % (probe, method, tilted, aligned_error, ratio))
                if ratio > 1.5 or tilted > bounds[probe]:
                    failures.append("%s: %s's inclined error %.4f (bound %.2f), %.2f times the axis-aligned (target 1.5)"
                                    % (probe, method, tilted, bounds[probe], ratio))

        # cracks (the UL-SPH's visibility criterion) on the axis-aligned half-plane at dx = 0.25: one
        # through the whole box between the load and the receiver leaves the receiver at rest; one from
        # the surface to depth 2.5 blocks most of the Rayleigh pulse (measured at 0.125: peak 0.055
        # against 0.146 uncracked) and leaves the load centre as it was
        with open(os.path.join(args.scenes, "lamb2d_halfplane.toml")) as f:
            halfplane = f.read()
        peaks = {}
        for label, crack in (("none", ""), ("through", "[[crack]]\nfrom = [1.0, 0.5]\nto = [1.0, -8.0]\n"),
                             ("partial", "[[crack]]\nfrom = [1.0, 0.5]\nto = [1.0, -2.5]\n")):
            scene = os.path.join(work, "crack-%s.toml" % label)
            with open(scene, "w") as f:
                f.write(halfplane + "\n" + crack)
            out = os.path.join(work, "crack-" + label)
            code, text = run([args.solid, "--scene", scene, "--out", out, "--quiet", "--set", "study.spacings=[0.25]",
                              "--set", 'study.methods=["updated_lagrangian_sph", "total_lagrangian_sph"]'])
            if code != 0:
                failures.append("crack %s: exit %d\n%s" % (label, code, text))
                continue
            for case in ("ulsph_0.25", "tlsph_0.25"):
                with open(os.path.join(out, case + "-probes.csv")) as f:
                    rows = list(csv.DictReader(f))
                peaks[(label, case)] = {p: max(abs(float(r[p])) for r in rows) for p in ("centre", "receiver")}
        for case in ("ulsph_0.25", "tlsph_0.25"):
            if any((label, case) not in peaks for label in ("none", "through", "partial")):
                continue
            none, through, partial = peaks[("none", case)], peaks[("through", case)], peaks[("partial", case)]
            print("cracks, %s: receiver peak %.4g uncracked, %.4g behind a crack through the box, %.4g behind one to "
                  "depth 2.5; centre %.4f, %.4f" % (case, none["receiver"], through["receiver"], partial["receiver"],
                                                    none["centre"], partial["centre"]))
            if not through["receiver"] < 1e-12:
                failures.append("%s: a crack through the box does not stop the receiver: peak %g" % (case, through["receiver"]))
            if not partial["receiver"] < 0.6 * none["receiver"]:
                failures.append("%s: a crack to depth 2.5 does not block the Rayleigh pulse" % case)
            if abs(partial["centre"] / none["centre"] - 1) > 0.05:
                failures.append("%s: a crack 1 away changes the load centre's peak by more than 5 %%" % case)
        with open(os.path.join(work, "crack-partial.toml")) as f:
            cracked = f.read()
        with open(os.path.join(work, "crack-vwsph.toml"), "w") as f:
            f.write(cracked.replace('methods = ["very_weak_sph", "reproducing_kernel", "updated_lagrangian_sph", '
                                    '"total_lagrangian_sph"]', 'methods = ["very_weak_sph"]'))

        # a fixed named surface ([[surface_boundary]]): a ball of radius 0.75 at (3, -1.5) under the
        # surface, a cavity (free) or a rigid inclusion (fixed); the probe on its top moves with the
        # cavity (measured peak 0.23, 0.11, 0.15 by RK, UL-SPH, TL-SPH) and barely with the inclusion
        # (0.0015, 0.0013, 0.0054)
        inclusion = halfplane.replace('solid = "box & ground"', 'solid = "box & ground - inclusion"') + \
            '\n[[shape]]\nname = "inclusion"\ntype = "ball"\ncentre = [3.0, -1.5]\nradius = 0.75\n' \
            '\n[[probe]]\nname = "top"\nposition = [3.0, -0.75]\nquantity = "velocity"\ncomponent = "y"\n'
        fixed = '\n[[surface_boundary]]\nsurface = "inclusion.surface"\ntype = "fixed"\n'
        tops = {}
        for label, text in (("cavity", inclusion), ("rigid", inclusion + fixed)):
            scene = os.path.join(work, label + ".toml")
            with open(scene, "w") as f:
                f.write(text)
            out = os.path.join(work, label)
            code, text_out = run([args.solid, "--scene", scene, "--out", out, "--quiet", "--set", "study.spacings=[0.25]",
                                  "--set", 'study.methods=["reproducing_kernel", "updated_lagrangian_sph", '
                                  '"total_lagrangian_sph"]'])
            if code != 0:
                failures.append("%s inclusion: exit %d\n%s" % (label, code, text_out))
                continue
            for case in ("rk_0.25", "ulsph_0.25", "tlsph_0.25"):
                with open(os.path.join(out, case + "-probes.csv")) as f:
                    tops[(label, case)] = max(abs(float(r["top"])) for r in csv.DictReader(f))
        for case in ("rk_0.25", "ulsph_0.25", "tlsph_0.25"):
            if ("rigid", case) not in tops or ("cavity", case) not in tops:
                continue
            print("fixed surface, %s: top of the ball %.4f as a cavity, %.4f as a rigid inclusion" %
                  (case, tops[("cavity", case)], tops[("rigid", case)]))
            if not tops[("rigid", case)] < 0.05 * tops[("cavity", case)]:
                failures.append("%s: the fixed surface moves (%.4f against the cavity's %.4f)" %
                                (case, tops[("rigid", case)], tops[("cavity", case)]))
        with open(os.path.join(work, "rigid-vwsph.toml"), "w") as f:
            f.write((inclusion + fixed).replace('methods = ["very_weak_sph", "reproducing_kernel", "updated_lagrangian_sph", '
                                                '"total_lagrangian_sph"]', 'methods = ["very_weak_sph"]'))

        with open(os.path.join(work, "open.stl"), "w") as f:
            f.write(OPEN_STL)
        with open(os.path.join(work, "open.toml"), "w") as f:
            f.write(BLOCK)
        cavity = os.path.join(args.scenes, "layered_cavity.toml")
        inclined_scene = os.path.join(args.scenes, "lamb2d_inclined.toml")
        cases = [
            ([cavity, "--set", "shape[2].centre=[50.0, 50.0]"], "shape[2].type", "lies outside the geometry box"),
            ([cavity, "--set", "geometry.solid=cavity - cavity"], "geometry.solid", "is empty"),
            ([cavity, "--set", "region[0].solid=cavity"], "region[0].solid", "holds no point of the solid"),
            ([os.path.join(work, "open.toml")], "shape[0].type", "open"),
            ([inclined_scene, "--set", "load[0].surface=nothing.plane"], "load[0].surface", "not '<shape>.<surface>'"),
            ([inclined_scene, "--set", "probe[1].position=[0.0, 3.0]"], "probe[1].position", "outside the solid"),
            ([inclined_scene, "--set", "geometry.solid=box & grund"], "geometry.solid", "names no shape 'grund'"),
            ([inclined_scene, "--set", "boundary[0].type=fixed"], "boundary[0].type", "free and transmitting"),
            ([cavity, "--set", "method.name=reproducing_kernel"], "load[0].type",
             "reproducing_kernel does not support moment_tensor loads"),
            ([os.path.join(work, "inclined-region.toml")], "region",
             "reproducing_kernel does not support materials by region; supported by: very_weak_sph"),
            ([os.path.join(work, "crack-vwsph.toml")], "crack",
             "very_weak_sph does not support cracks; supported by: updated_lagrangian_sph, total_lagrangian_sph"),
            ([os.path.join(work, "rigid-vwsph.toml")], "surface_boundary",
             "very_weak_sph does not support fixed surfaces of a solid"),
            ([os.path.join(work, "rigid.toml"), "--set", "surface_boundary[0].surface=ground.plane", "--set",
              'study.methods=["reproducing_kernel"]'], "load[0].surface", "held fixed"),
        ]
        with open(inclined_scene) as f:
            text = f.read()
        with open(os.path.join(work, "inclined-region.toml"), "w") as f:
            f.write(text.replace('name = "very_weak_sph"', 'name = "reproducing_kernel"').replace('variant = "galerkin"\n', '')
                    .replace('cells = "cut"\n', '') +
                    '\n[[region]]\nname = "top"\nsolid = "box & ground"\ndensity = 1.0\nlambda = 2.0\nmu = 2.0\n')
        for k, (scene_args, key, text) in enumerate(cases):
            refused = os.path.join(work, "refused-%d" % k)
            code, out = run([args.solid, "--scene"] + scene_args + ["--out", refused, "--quiet"])
            if code != 2 or key not in out or (text and text not in out) or os.path.exists(refused):
                failures.append("%s: exit %d (want 2 naming %s%s, nothing written)\n%s" %
                                (" ".join(scene_args[1:]) or scene_args[0], code, key, ", " + text if text else "", out))
            else:
                print("refused: " + out.strip().splitlines()[-1])
        # a receiver grid across the cavity: the 2 of its 25 points inside the cavity are left out
        with open(cavity) as f:
            text = f.read()
        grid = os.path.join(work, "grid.toml")
        with open(grid, "w") as f:
            f.write(text + '\n[[probe_grid]]\nname = "map"\nlower = [0.5, -2.5]\nupper = [2.5, -0.5]\n'
                    'counts = [5, 5]\ndirection = [0.0, 1.0]\n')
        out = os.path.join(work, "grid")
        code, text_out = run([args.solid, "--scene", grid, "--out", out, "--quiet", "--set", "geometry.spacing=0.25",
                              "--set", "integrator.end_time=1", "--set", "output.png=false", "--set", "output.vtk=false"])
        columns = []
        if code == 0:
            with open(os.path.join(out, "cut_0.25-probes.csv")) as f:
                columns = [c for c in f.readline().strip().split(",") if c.startswith("map_")]
        if code != 0 or len(columns) != 23:
            failures.append("probe grid: exit %d, %d receivers (want 23: 25 less the 2 in the cavity)\n%s" %
                            (code, len(columns), text_out))
        else:
            print("probe grid: 23 of 25 receivers in the solid")
        # two overlapping regions: refused without the rule, run with it
        with open(cavity) as f:
            text = f.read()
        overlapping = text + '\n[[region]]\nname = "lens"\nsolid = "cavity_halo"\ndensity = 1.0\nlambda = 2.0\nmu = 2.0\n' \
            '\n[[shape]]\nname = "cavity_halo"\ntype = "ball"\ncentre = [-3.0, -2.0]\nradius = 1.0\n'
        scene = os.path.join(work, "overlap.toml")
        with open(scene, "w") as f:
            f.write(overlapping)
        code, out = run([args.solid, "--scene", scene, "--check"])
        if code != 2 or "region[1].solid" not in out or "overlap" not in out:
            failures.append("overlapping regions: exit %d (want 2 naming region[1].solid)\n%s" % (code, out))
        else:
            print("refused: " + out.strip().splitlines()[-1])
        code, out = run([args.solid, "--scene", scene, "--check", "--set", "geometry.region_overlap=last"])
        if code != 0:
            failures.append("overlapping regions with region_overlap = last: exit %d\n%s" % (code, out))
    if failures:
        print("FAILED:\n" + "\n".join(failures))
        sys.exit(1)
    print("the solid study: inclined within 1.5 times the axis-aligned errors (cut cells, RK collocation, UL- and TL-SPH); "
          "bad geometry refused by key")


if __name__ == "__main__":
    main()
