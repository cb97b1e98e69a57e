"""The configurations of the speed-accuracy sweep (analysis/tradeoff/).

A Point is one driver process pinned to one configuration: one problem, one resolution, one
kernel and support, one integrator, one time-step fraction. Everything else in the problem's scene
keeps the value of its file in data/scenes/, so a point can be rerun by hand from its `command`.
"""
from dataclasses import dataclass

# What each problem's error is, as the driver computes it (the CSV's error_measure column).
ERROR_MEASURES = {
    "standing_wave_1d": "relative L2 of u at T over the particles (norm of the mode shape)",
    "bar_fixed_free_1d": "relative L2 of u at T on 2001 points",
    "manufactured_2d": "relative L2 of u at T on a 4x finer grid",
    "bar_impact_1d": "relative L1 of v at T over the particles",
    "lamb_3d": "relative L2 of v_z over 0-6 s, worst of the centre, surface (2 away) and buried (1 deep) receivers",
    "lamb_2d": "relative L2 of v_y over 0-6 s, worst of the centre, surface (2 away) and buried (1 deep) receivers",
    "plane_wave_2d": "relative L2 of u at T (2 periods) over the nodes (the SEM: GLL quadrature weights)",
}


@dataclass(frozen=True)
class Point:
    problem: str          # a key of ERROR_MEASURES
    method: str           # the legend entry: FD, RKCM, RBCM, UL-SPH, VW-SPH ...
    driver: str           # executable under <build>/drivers/
    scene: str            # file under data/scenes/
    resolution: str       # "cells=64", "nodes=161", "dx=0.0025": the driver's own resolution knob
    kernel: str           # "-" when the method has none (the finite-difference stencil)
    support: str          # RK: a/h; RBF: shape a_r/h; SPH: h/dx; "-" when none
    integrator: str
    dt_fraction: float    # integrator.cfl: the fraction of the driver's stable step
    sets: tuple = ()      # --set overrides that pin the configuration
    drop: tuple = ()      # dotted scene keys removed from the scene file (those --set cannot unset)

    @property
    def config_id(self):
        """A stable key: the resume logic finds finished points by it, so never reorder it."""
        return "|".join([self.problem, self.method, self.resolution, self.kernel, self.support,
                         self.integrator, f"{self.dt_fraction:g}"])


def wave1d(cells, integrator="central_difference", cfl=0.5):
    return Point("standing_wave_1d", "FD", "wave1d", "wave1d.toml", f"cells={cells}", "-", "-",
                 integrator, cfl,
                 (f"study.cells=[{cells}]", f'study.integrators=["{integrator}"]', f"integrator.cfl={cfl}")
                 # above the limit on purpose: wave1d refuses such a step (exit 2) unless asked to run it
                 + (("stability.allow_growth=true",) if cfl > 1 else ()))


def bar1d_rk(nodes, order=2, ratio=3.3, integrator="central_difference", cfl=0.5):
    return Point("bar_fixed_free_1d", "RKCM", "bar1d", "bar1d.toml", f"nodes={nodes}",
                 f"cubic_b_spline_m{order}", f"{ratio:g}", integrator, cfl,
                 (f"study.nodes=[{nodes}]", f"method.order={order}", f"method.support_ratio={ratio}",
                  f"integrator.name={integrator}", f"integrator.cfl={cfl}")
                 # above the limit on purpose: bar1d refuses such a step (exit 2) unless asked to run it
                 + (("stability.allow_growth=true",) if cfl > 1 else ()))


def bar1d_rb(nodes, basis="inverse_multiquadric", shape=3.0, integrator="central_difference", cfl=0.5):
    return Point("bar_fixed_free_1d", "RBCM", "bar1d", "bar1d.toml", f"nodes={nodes}", basis, f"{shape:g}",
                 integrator, cfl,
                 (f"study.nodes=[{nodes}]", "method.name=radial_basis", f"method.basis={basis}",
                  f"method.shape_ratio={shape}", f"integrator.name={integrator}", f"integrator.cfl={cfl}"),
                 drop=("method.order", "method.support_ratio"))


def plane2d(cells, order=2, ratio=2.5, integrator="central_difference", cfl=0.5):
    return Point("manufactured_2d", "RKCM", "plane2d", "plane2d.toml", f"cells={cells}",
                 f"cubic_b_spline_m{order}", f"{ratio:g}", integrator, cfl,
                 (f"study.cells=[{cells}]", f"method.order={order}", f"method.support_ratio={ratio}",
                  f"integrator.name={integrator}", f"integrator.cfl={cfl}"))


def bar1d_sph(per_bar, kernel="cubic_spline", ratio=2.0, integrator="leapfrog", cfl=1.0):
    # dx = 1 / per_bar divides each bar exactly, so the driver does not adjust it.
    dx = 1.0 / per_bar
    return Point("bar_impact_1d", "UL-SPH", "bar1d-sph", "bar1d-sph.toml", f"dx={dx:g}", kernel, f"{ratio:g}",
                 integrator, cfl,
                 (f"study.spacings=[{dx!r}]", f"geometry.spacing={dx!r}", "output.vtk=false",
                  f"method.kernel={kernel}", f"method.smoothing_length_ratio={ratio}",
                  f"integrator.name={integrator}", f"integrator.cfl={cfl}"))


# The problems several methods solve, each with its own panel and answer (docs/studies/which-method.md).
SHARED_PROBLEMS = ("plane_wave_2d", "lamb_2d", "lamb_3d")


def lamb3d(dx, variant="consistent", kernel="cubic_spline", ratio=1.0, cfl=0.5, dimension=3):
    """A Lamb problem by very weak SPH: the 3-D square load (lamb3d) or, with dimension=2, the
    plane-strain strip load (lamb2d), at one spacing, scored at the scene's three receivers."""
    sets = [f"geometry.spacing={dx}", f"study.spacings=[{dx}]", "output.vtk=false",
            "study.compare_published=false", "study.strong_smoothing_rate=0", "study.kernel_floor=false",
            f"integrator.cfl={cfl}"]
    if variant == "galerkin":
        # The scene's own method (the tent kernel as test and trial function, no filter, on the
        # lattice stencils): no kernel or smoothing length to choose.
        kernel, ratio = "tent", "-"
    else:
        sets += [f"method.kernel={kernel}", f"method.smoothing_length_ratio={ratio}"]
    if variant == "consistent":
        # The study's filter rate, 0.25 c_s / dx (0.5 at dx = 0.5): given here at this run's spacing.
        sets += ["method.variant=consistent", f"method.smoothing_rate={0.25 / dx:g}"]
    elif variant == "published":
        # The scheme as printed with the paper's settings: what the lamb3d driver's published_<dx> cases use.
        sets += ["method.variant=published", "method.smoothing_rate=0.77", "method.smoothing_order=1",
                 "method.smoothing_rate_scales_with_spacing=false", "method.deconvolution=true"]
    name = f"lamb{dimension}d"
    return Point(f"lamb_{dimension}d", f"VW-SPH {variant}", name, f"{name}.toml", f"dx={dx:g}", kernel,
                 ratio if isinstance(ratio, str) else f"{ratio:g}",
                 "central_difference", cfl, tuple(sets),
                 drop=("study.free_block_lower", "study.free_block_upper"))


def lamb2d(dx, variant="galerkin", kernel="cubic_spline", ratio=1.0, cfl=0.5):
    return lamb3d(dx, variant, kernel, ratio, cfl, dimension=2)


def lamb2d_rk(dx, order=2, ratio=2.5, integrator="central_difference", cfl=0.5, dimension=2):
    """A Lamb problem by RK collocation (lamb2d or, with dimension=3, lamb3d; method.name =
    reproducing_kernel): traction rows on the free face, the other faces fixed (in 2-D their first
    reflection reaches a receiver after the error window, in 3-D at t = 2.6, inside it), one spacing."""
    sets = (f"method.name=reproducing_kernel", f"method.order={order}", f"method.support_ratio={ratio}",
            f"geometry.spacing={dx}", f"study.spacings=[{dx}]", "output.vtk=false",
            f"integrator.name={integrator}", f"integrator.cfl={cfl}")
    name = f"lamb{dimension}d"
    return Point(f"lamb_{dimension}d", "RKCM", name, f"{name}.toml", f"dx={dx:g}", f"cubic_b_spline_m{order}",
                 f"{ratio:g}", integrator, cfl, sets,
                 drop=("study.free_block_lower", "study.free_block_upper"))


def lamb3d_rk(dx, order=2, ratio=2.2, integrator="central_difference", cfl=0.5):
    """The 3-D Lamb problem by RK collocation (lamb3d): a / h = 2.2 by default, the widest 3-D support
    whose interior rows do not grow (2.5 is refused)."""
    return lamb2d_rk(dx, order, ratio, integrator, cfl, dimension=3)


def lamb2d_ulsph(dx, alpha=1.0):
    """The 2-D Lamb problem by the updated-Lagrangian SPH at small amplitude (lamb2d, method.name =
    updated_lagrangian_sph): cubic spline h/dx 1.3, kernel-gradient correction, Monaghan viscosity
    alpha, leapfrog at the method's own step criteria (it takes no step fraction: 1 here)."""
    sets = ("method.name=updated_lagrangian_sph", f"method.viscosity_alpha={alpha}", f"geometry.spacing={dx}",
            f"study.spacings=[{dx}]", "output.vtk=false")
    return Point("lamb_2d", f"UL-SPH alpha {alpha:g}", "lamb2d", "lamb2d.toml", f"dx={dx:g}", "cubic_spline",
                 "1.3", "leapfrog", 1.0, sets, drop=("study.free_block_lower", "study.free_block_upper"))


def lamb3d_ulsph(dx, alpha=1.0):
    """The 3-D Lamb problem by the updated-Lagrangian SPH at small amplitude (lamb3d, method.name =
    updated_lagrangian_sph), as lamb2d_ulsph: the scene's 7 x 7 x 7 box with every face free (the
    method has no dashpots; the reflections move its errors by 0.012 at most at dx = 0.25)."""
    sets = ("method.name=updated_lagrangian_sph", f"method.viscosity_alpha={alpha}", f"geometry.spacing={dx}",
            f"study.spacings=[{dx}]", "output.vtk=false")
    return Point("lamb_3d", f"UL-SPH alpha {alpha:g}", "lamb3d", "lamb3d.toml", f"dx={dx:g}", "cubic_spline",
                 "1.3", "leapfrog", 1.0, sets, drop=("study.free_block_lower", "study.free_block_upper"))


def lamb2d_sem(dx, order=4, cfl=0.5, dimension=2):
    """A Lamb problem by the spectral-element reference (lamb2d or, with dimension=3, lamb3d;
    method.name = spectral_element): GLL order N on square / cubic elements N spacings wide (so dx
    is the mean node spacing, as for the lattice methods), dashpots on the transmitting faces,
    central difference."""
    sets = ("method.name=spectral_element", f"method.order={order}", f"geometry.spacing={dx}",
            f"study.spacings=[{dx}]", "output.vtk=false", f"integrator.cfl={cfl}")
    name = f"lamb{dimension}d"
    return Point(f"lamb_{dimension}d", "SEM", name, f"{name}.toml", f"dx={dx:g}", f"gll_n{order}", "-",
                 "central_difference", cfl, sets, drop=("study.free_block_lower", "study.free_block_upper"))


def lamb3d_sem(dx, order=4, cfl=0.5):
    return lamb2d_sem(dx, order, cfl, dimension=3)


PLANE_WAVE_METHODS = {"finite_difference": "FD", "vwsph_consistent": "VW-SPH consistent",
                      "vwsph_published": "VW-SPH published", "vwsph_galerkin": "VW-SPH galerkin", "rkcm": "RKCM",
                      "ulsph": "UL-SPH alpha 0", "ulsph_corrected": "UL-SPH corrected alpha 0",
                      "spectral_element": "SEM"}


# The planewave scene names its method as the catalogue does (mfwave methods); the sweep keeps the
# lattice tools' row ids as its short labels.
CATALOGUE_SPELLING = {
    "finite_difference": ["study.method=finite_difference"],
    "vwsph_published": ["study.method=very_weak_sph", "study.variant=published"],
    "vwsph_consistent": ["study.method=very_weak_sph", "study.variant=consistent"],
    "vwsph_galerkin": ["study.method=very_weak_sph", "study.variant=galerkin"],
    "rkcm": ["study.method=reproducing_kernel"],
    "ulsph": ["study.method=updated_lagrangian_sph"],
    "ulsph_corrected": ["study.method=updated_lagrangian_sph", "study.gradient_correction=true"],
    "spectral_element": ["study.method=spectral_element"],
}


def planewave(cells, method="vwsph_consistent", kernel="cubic_spline", ratio=1.3, integrator="central_difference",
              cfl=0.5, order=4):
    """A P wave, two wavelengths across the periodic unit square, over two periods (planewave driver).
    ulsph / ulsph_corrected: the updated-Lagrangian SPH linearised about rest (viscosity off, hence
    "alpha 0"); spectral_element: GLL order `order` on periodic elements `order` cells wide."""
    if method == "rkcm":
        kernel_name, support = "cubic_b_spline_m2", ratio
        sets = [f"study.rk_support_ratio={ratio}"]
    elif method == "spectral_element":
        kernel_name, support, sets = f"gll_n{order}", "-", [f"study.sem_order={order}"]
    elif method in ("finite_difference", "vwsph_galerkin"):
        kernel_name, support, sets = ("-" if method == "finite_difference" else "tent"), "-", []
    else:
        kernel_name, support = kernel, ratio
        sets = [f"study.kernel={kernel}", f"study.smoothing_length_ratio={ratio}"]
    support_text = support if support == "-" else f"{support:g}"
    return Point("plane_wave_2d", PLANE_WAVE_METHODS[method], "planewave", "planewave.toml", f"cells={cells}",
                 kernel_name, support_text, integrator, cfl,
                 tuple(CATALOGUE_SPELLING[method] + [f"study.cells={cells}", f"integrator.name={integrator}",
                                                      f"integrator.cfl={cfl}"] + sets))


def _dedupe(points):
    seen, unique = set(), []
    for p in points:
        if p.config_id not in seen:
            seen.add(p.config_id)
            unique.append(p)
    return unique


def default_sweep():
    """229 points, about 5 minutes on 2 idle cores (the largest: lamb3d's Galerkin variant at dx = 0.0625, about 40 s; the UL-SPH on lamb3d at 0.25, about 40 s; the UL-SPH on lamb2d at 0.0625, about 30 s; RK collocation on lamb3d at 0.5 and on lamb2d at 0.125, about 20 s each)."""
    pts = []
    # Standing wave, finite differences: every integrator over resolutions, then step fractions
    # (1.0 is the 1-D "magic" step of central differences; 1.05 is above the limit and fails).
    for integ in ("central_difference", "leapfrog", "newmark", "arkode"):
        pts += [wave1d(c, integ) for c in (32, 64, 128, 256, 512, 1024, 2048)]
    pts += [wave1d(c, cfl=f) for f in (0.25, 0.9, 1.0, 1.05) for c in (64, 256, 1024)]
    # Fixed-free bar, RK collocation: resolutions, supports, order, Newmark, fractions.
    pts += [bar1d_rk(n) for n in (21, 41, 81, 161, 321, 641, 1281)]
    pts += [bar1d_rk(n, ratio=r) for r in (2.5, 4.3) for n in (41, 161)]
    pts += [bar1d_rk(n, order=3) for n in (41, 161)]
    pts += [bar1d_rk(n, integrator="newmark") for n in (41, 161, 641)]
    pts += [bar1d_rk(161, cfl=f) for f in (0.25, 0.9, 1.05)]
    # Manufactured plane-strain solution, RK collocation (a/h = 3.0 is the unstable support).
    pts += [plane2d(c) for c in (8, 12, 16, 24, 32, 48)]
    pts += [plane2d(c, ratio=2.2) for c in (16, 32)]
    pts += [plane2d(c, integrator="newmark") for c in (16, 32)]
    pts += [plane2d(c, cfl=0.9) for c in (16, 32)]
    pts += [plane2d(16, ratio=3.0)]
    # Two bars meeting, updated-Lagrangian SPH: resolutions, kernels, h/dx, integrators, fractions
    # (a factor on the method's own step criteria, which carry a Courant number of 0.3).
    pts += [bar1d_sph(n) for n in (25, 50, 100, 200, 400, 800, 1600)]
    pts += [bar1d_sph(n, kernel=k) for k in ("quintic_spline", "wendland_c2", "wendland_c4", "gaussian")
            for n in (400, 1600)]
    pts += [bar1d_sph(n, ratio=r) for r in (1.3, 3.0) for n in (400, 1600)]
    pts += [bar1d_sph(n, integrator=i) for i in ("forward_euler", "predictor_corrector", "arkode")
            for n in (400, 1600)]
    pts += [bar1d_sph(n, cfl=f) for f in (0.5, 3.0, 6.0, 8.0) for n in (400, 1600)]
    # 3-D Lamb problem, very weak form SPH (the largest first, so it is not the straggler): the
    # shipped Galerkin variant to dx = 0.0625 (1.4 million particles on the lattice stencils), the
    # consistent and published ones to 0.125.
    pts = [lamb3d(0.0625, variant="galerkin"), lamb3d(0.125), lamb3d(0.125, kernel="wendland_c2"),
           lamb3d(0.125, variant="published")] + pts
    pts += [lamb3d(dx, variant="galerkin") for dx in (0.5, 0.25, 0.125)]
    pts += [lamb3d(dx) for dx in (0.5, 0.25)]
    pts += [lamb3d(dx, variant="published") for dx in (0.5, 0.25)]
    pts += [lamb3d(dx, kernel="wendland_c2") for dx in (0.5, 0.25)]
    pts += [lamb3d(dx, cfl=0.9) for dx in (0.5, 0.25)]
    # 3-D Lamb problem, the spectral-element reference (the box, 7 wide, takes elements of 1 and 0.5).
    pts += [lamb3d_sem(0.5, order=2), lamb3d_sem(0.25), lamb3d_sem(0.125), lamb3d_sem(0.125, order=2),
            lamb3d_sem(0.25, cfl=0.9)]
    # 3-D Lamb problem, the updated-Lagrangian SPH at small amplitude (alpha = 1, lamb2d's best).
    pts += [lamb3d_ulsph(dx) for dx in (0.5, 0.25)]
    # 3-D Lamb problem, RK collocation (m = 2, a/h = 2.2): dx = 0.5 only, about 25 s on one core
    # (dx = 0.25 takes over ten minutes and about 4 GiB: docs/studies/lamb3d.md).
    pts += [lamb3d_rk(0.5)]
    # 2-D Lamb problem (strip load), very weak form SPH: every variant over spacings.
    pts += [lamb2d(dx) for dx in (0.5, 0.25, 0.125, 0.0625, 0.03125)]
    pts += [lamb2d(dx, variant="consistent") for dx in (0.5, 0.25, 0.125, 0.0625, 0.03125)]
    pts += [lamb2d(dx, variant="published") for dx in (0.5, 0.25, 0.125)]
    pts += [lamb2d(dx, cfl=0.9) for dx in (0.125, 0.0625)]
    # 2-D Lamb problem, RK collocation (m = 2, a/h = 2.5; 2.2 the narrowest stable support, Newmark).
    pts += [lamb2d_rk(dx) for dx in (0.5, 0.25, 0.125)]
    pts += [lamb2d_rk(dx, ratio=2.2) for dx in (0.25, 0.125)]
    pts += [lamb2d_rk(0.25, integrator="newmark"), lamb2d_rk(0.25, cfl=0.9)]
    # 2-D Lamb problem, the updated-Lagrangian SPH at small amplitude (alpha = 1, its measured best; 0 beside).
    pts += [lamb2d_ulsph(dx) for dx in (0.5, 0.25, 0.125, 0.0625)]
    pts += [lamb2d_ulsph(0.125, alpha=0.0)]
    # 2-D Lamb problem, the spectral-element reference: order 4 over spacings, orders 1, 2, 8, fraction 0.9.
    pts += [lamb2d_sem(dx) for dx in (0.5, 0.25, 0.125, 0.0625, 0.03125)]
    pts += [lamb2d_sem(0.125, order=n) for n in (1, 2, 8)]
    pts += [lamb2d_sem(dx, cfl=0.9) for dx in (0.125, 0.0625)]
    # Plane wave in a periodic box: every linear method on the same problem.
    pts += [planewave(c, m) for m in ("finite_difference", "vwsph_consistent", "vwsph_published", "vwsph_galerkin")
            for c in (16, 32, 64, 128, 256)]
    pts += [planewave(c, "vwsph_consistent", kernel=k, ratio=r) for k, r in (("wendland_c2", 1.3), ("cubic_spline", 1.5))
            for c in (32, 128)]
    pts += [planewave(c, "rkcm", ratio=2.5, integrator="newmark") for c in (16, 32, 64, 128)]
    pts += [planewave(c, m, cfl=f) for m in ("finite_difference", "vwsph_consistent") for f in (0.9, 1.0)
            for c in (32, 128)]
    pts += [planewave(c, m, integrator=i) for m in ("finite_difference", "vwsph_consistent")
            for i in ("newmark", "arkode") for c in (32, 128)]
    # ... the updated-Lagrangian SPH linearised about rest, plain and kernel-gradient corrected, and
    # the spectral elements (order 4 over resolutions, orders 2 and 8, the step fraction 0.9).
    pts += [planewave(c, m) for m in ("ulsph", "ulsph_corrected") for c in (16, 32, 64, 128, 256)]
    pts += [planewave(c, "spectral_element") for c in (16, 32, 64, 128)]
    pts += [planewave(c, "spectral_element", order=n) for n in (2, 8) for c in (32, 64)]
    pts += [planewave(c, "spectral_element", cfl=0.9) for c in (32, 64)]
    return _dedupe(pts)


def full_sweep():
    """The default points and 210 more: finer resolutions, more kernels and fractions (about 15 minutes on 2 cores; RK collocation on lamb2d at dx = 0.0625 alone takes 3 minutes, the UL-SPH on lamb3d at 0.125 about 9)."""
    pts = default_sweep()
    for integ in ("central_difference", "leapfrog", "newmark", "arkode"):
        pts += [wave1d(c, integ) for c in (4096, 8192)]
    pts += [wave1d(c, cfl=f) for f in (0.1, 0.25, 0.75, 0.9, 1.0) for c in (32, 128, 512, 2048, 8192)]
    pts += [bar1d_rk(n) for n in (2561,)]
    pts += [bar1d_rk(n, ratio=r) for r in (2.5, 4.3, 5.3) for n in (21, 81, 321, 641)]
    pts += [bar1d_rk(n, order=3) for n in (21, 81, 321, 641)]
    pts += [bar1d_rk(n, integrator="newmark") for n in (21, 81, 321, 1281)]
    pts += [bar1d_rk(n, cfl=f) for f in (0.25, 0.75, 0.9) for n in (41, 641)]
    pts += [bar1d_rb(n) for n in (21, 41, 81)]
    pts += [bar1d_rb(n, shape=s) for s in (1.0, 6.0) for n in (21, 41)]
    pts += [plane2d(c) for c in (64,)]
    pts += [plane2d(c, ratio=2.2) for c in (8, 12, 24, 48)]
    pts += [plane2d(c, order=3, ratio=3.3) for c in (8, 16, 32)]
    pts += [plane2d(c, integrator="newmark") for c in (8, 24, 48)]
    pts += [plane2d(c, cfl=f) for f in (0.25, 0.75, 0.9) for c in (8, 24, 48)]
    pts += [bar1d_sph(n) for n in (3200, 6400)]
    pts += [bar1d_sph(n, kernel=k) for k in ("quintic_spline", "wendland_c2", "wendland_c4", "gaussian")
            for n in (100, 200, 800, 3200)]
    pts += [bar1d_sph(n, ratio=r) for r in (1.3, 1.5, 2.5, 3.0) for n in (100, 200, 800, 3200)]
    pts += [bar1d_sph(n, integrator=i) for i in ("forward_euler", "predictor_corrector", "arkode")
            for n in (100, 200, 800, 3200)]
    pts += [bar1d_sph(n, cfl=f) for f in (0.5, 2.0, 3.0, 4.0, 6.0) for n in (100, 200, 800, 3200)]
    pts += [lamb3d(0.5, kernel="quintic_spline"), lamb3d(0.5, kernel="wendland_c2", ratio=1.3)]
    pts += [lamb3d(dx, cfl=f) for f in (0.25, 0.75) for dx in (0.5, 0.25)] + [lamb3d(0.125, cfl=0.9)]
    pts += [planewave(c, m) for m in ("finite_difference", "vwsph_consistent") for c in (512,)]
    pts += [planewave(c, "vwsph_consistent", kernel=k, ratio=r) for k, r in (("wendland_c2", 1.3), ("cubic_spline", 1.5),
                                                                             ("quintic_spline", 1.0))
            for c in (16, 64, 256)]
    pts += [planewave(c, "rkcm", ratio=r, integrator="newmark") for r in (2.2, 2.5) for c in (256,)]
    pts += [planewave(c, m) for m in ("ulsph", "ulsph_corrected") for c in (512,)]
    pts += [planewave(256, "spectral_element")] + [planewave(128, "spectral_element", order=n) for n in (2, 8)]
    pts += [planewave(c, m, cfl=f) for m in ("finite_difference", "vwsph_consistent") for f in (0.25, 0.75)
            for c in (32, 128, 512)]
    pts += [lamb2d(0.015625), lamb2d(0.015625, variant="consistent")]
    pts += [lamb2d(dx, kernel=k, variant="consistent") for k in ("wendland_c2", "quintic_spline") for dx in (0.125, 0.0625)]
    pts += [lamb2d_rk(0.0625), lamb2d_rk(0.125, order=3, ratio=3.3), lamb2d_rk(0.125, integrator="newmark")]
    pts += [lamb2d_ulsph(dx, alpha=0.0) for dx in (0.25, 0.0625)]
    pts += [lamb3d_sem(0.0625), lamb3d_sem(0.125, cfl=0.9), lamb3d_sem(0.0625, order=2)]
    pts += [lamb3d_ulsph(0.125)]  # about 9 minutes on one free core (185193 particles, 469 steps)
    pts += [lamb2d_sem(0.015625)] + [lamb2d_sem(dx, order=n) for n in (2, 8) for dx in (0.0625, 0.03125)]
    return _dedupe(pts)


def smoke_sweep():
    """Four points in well under a second each, for the ctest check of the tool itself: three
    resolutions of one method (the error must fall) and one step above the stability limit."""
    return [wave1d(c) for c in (16, 32, 64)] + [wave1d(32, cfl=1.2)]


SWEEPS = {"default": default_sweep, "full": full_sweep, "smoke": smoke_sweep}
