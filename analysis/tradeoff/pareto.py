"""Pareto front and cheapest configuration per error target: pure functions, no files, no plotting.

Points are any objects; `cost` and `error` are functions of a point returning floats, both to be
minimised. Points whose cost or error is not finite are ignored.
"""
import math


def _usable(points, cost, error):
    return [p for p in points if math.isfinite(cost(p)) and math.isfinite(error(p))]


def dominates(a, b, cost, error):
    """a is at least as cheap and as accurate as b, and strictly better in one of the two."""
    ca, cb, ea, eb = cost(a), cost(b), error(a), error(b)
    return ca <= cb and ea <= eb and (ca < cb or ea < eb)


def pareto_front(points, cost, error):
    """The points no other point dominates, cheapest first. Quadratic, by the definition itself:
    sweeps hold hundreds of points, and the definition is what a reader can check."""
    usable = _usable(points, cost, error)
    front = [p for p in usable if not any(dominates(q, p, cost, error) for q in usable)]
    return sorted(front, key=lambda p: (cost(p), error(p)))


def cheapest_reaching(points, target, cost, error):
    """The cheapest point with error <= target (the most accurate among equally cheap ones), or None.
    It is always on the Pareto front."""
    reaching = [p for p in _usable(points, cost, error) if error(p) <= target]
    return min(reaching, key=lambda p: (cost(p), error(p))) if reaching else None


def cheapest_per_target(points, targets, cost, error):
    """[(target, point or None)] in the order of `targets`."""
    return [(t, cheapest_reaching(points, t, cost, error)) for t in targets]
