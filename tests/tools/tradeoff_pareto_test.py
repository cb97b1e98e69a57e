"""Unit checks of analysis/tradeoff/pareto.py (the Pareto front and the cheapest point per target) and of
report.py's per-problem, per-receiver answers."""
import math
import os
import random
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from analysis.tradeoff.pareto import cheapest_per_target, cheapest_reaching, dominates, pareto_front  # noqa: E402
from analysis.tradeoff.report import receiver_errors, report_text  # noqa: E402


def cost(p):
    return p[0]


def error(p):
    return p[1]


def staircase_front(points):
    """An independent construction: sort by cost, keep each point that beats the best error so far
    (points equal in both coordinates are all kept)."""
    front, best = [], math.inf
    for p in sorted(points):
        if p[1] < best or (front and p == front[-1]):
            front.append(p)
            best = min(best, p[1])
    return front


class ParetoFront(unittest.TestCase):
    def test_dominated_points_are_left_out(self):
        pts = [(1.0, 0.5), (2.0, 0.1), (3.0, 0.2), (0.5, 0.9), (2.0, 0.3)]
        self.assertEqual(pareto_front(pts, cost, error), [(0.5, 0.9), (1.0, 0.5), (2.0, 0.1)])

    def test_equal_cost_keeps_only_the_more_accurate(self):
        self.assertEqual(pareto_front([(1.0, 0.2), (1.0, 0.1)], cost, error), [(1.0, 0.1)])

    def test_identical_points_are_both_on_the_front(self):
        self.assertEqual(pareto_front([(1.0, 0.1), (1.0, 0.1)], cost, error), [(1.0, 0.1), (1.0, 0.1)])

    def test_points_without_finite_numbers_are_ignored(self):
        pts = [(1.0, math.nan), (math.inf, 1e-9), (2.0, 0.5)]
        self.assertEqual(pareto_front(pts, cost, error), [(2.0, 0.5)])
        self.assertEqual(pareto_front([], cost, error), [])

    def test_agrees_with_the_staircase_and_holds_both_extremes(self):
        rng = random.Random(8)
        for _ in range(200):
            pts = [(rng.choice([0.1, 0.2, 0.5, 1.0, 2.0]) * rng.randint(1, 3), 10 ** -rng.randint(0, 4))
                   for _ in range(rng.randint(1, 30))]
            front = pareto_front(pts, cost, error)
            self.assertEqual(front, staircase_front(pts))
            self.assertIn(min(pts), front)                              # the fastest (most accurate of ties)
            self.assertIn(min(pts, key=lambda p: (p[1], p[0])), front)  # the most accurate (cheapest of ties)
            for p in front:
                self.assertFalse(any(dominates(q, p, cost, error) for q in pts))


class CheapestPerTarget(unittest.TestCase):
    pts = [(0.01, 0.3), (0.1, 0.05), (1.0, 0.004), (0.5, 0.02), (5.0, 0.004)]

    def test_cheapest_reaching_each_target(self):
        got = cheapest_per_target(self.pts, (0.1, 0.01, 0.001), cost, error)
        self.assertEqual(got, [(0.1, (0.1, 0.05)), (0.01, (1.0, 0.004)), (0.001, None)])

    def test_the_target_itself_counts_as_reached(self):
        self.assertEqual(cheapest_reaching(self.pts, 0.05, cost, error), (0.1, 0.05))

    def test_the_answer_is_on_the_front(self):
        front = pareto_front(self.pts, cost, error)
        for _, best in cheapest_per_target(self.pts, (0.5, 0.1, 0.01), cost, error):
            self.assertIn(best, front)


def row(problem, method, wall, err, receivers="", peak=50.0):
    return {"config_id": f"{problem}|{method}|{wall}", "status": "ok", "exit_code": 0.0, "problem": problem,
            "method": method, "resolution": f"dx={wall}", "kernel": "-", "support_ratio": "-",
            "integrator": "central_difference", "dt_fraction": 0.5, "error": err, "error_measure": "L2",
            "wall_s": wall, "peak_mib": peak, "receiver_errors": receivers}


class Report(unittest.TestCase):
    rows = [row("lamb_2d", "A", 1.0, 0.08, "centre=0.05;receiver=0.08;buried=0.02"),
            row("lamb_2d", "B", 2.0, 0.02, "centre=0.02;receiver=0.01;buried=0.015", peak=80.0),
            row("lamb_2d", "A", 5.0, 0.009, "centre=0.009;receiver=0.005;buried=0.004"),
            row("standing_wave_1d", "FD", 0.1, 0.002)]

    def test_receiver_errors_are_read_back(self):
        self.assertEqual(receiver_errors(self.rows[0]), {"centre": 0.05, "receiver": 0.08, "buried": 0.02})
        self.assertEqual(receiver_errors(self.rows[3]), {})

    def test_each_problem_answers_each_target_and_each_receiver_with_time_and_memory(self):
        lines = report_text(self.rows).splitlines()
        shared = lines.index("Problems several methods solve (the cheapest configuration per target answers which method):")
        single = lines.index("Problems one method solves (its settings against each other):")
        self.assertLess(shared, single)
        lamb = lines[shared + 1:single]
        # Worst receiver: 10 % -> A at 1 s; 3 % -> B at 2 s (80 MiB); 1 % -> A at 5 s.
        self.assertIn("<= 10 %: 1 s, 50 MiB", next(l for l in lamb if "<= 10 %:" in l))
        self.assertIn("<= 3 %: 2 s, 80 MiB", next(l for l in lamb if "<= 3 %:" in l))
        self.assertIn("<= 1 %: 5 s", next(l for l in lamb if "<= 1 %:" in l))
        # The buried receiver alone reaches 3 % with A at 1 s already.
        at = lamb.index("    at the probe 'buried' alone:")
        self.assertIn("<= 3 %: 1 s", lamb[at + 2])
        # No front or answer across problems.
        self.assertNotIn("over all problems", "\n".join(lines))


if __name__ == "__main__":
    unittest.main()
