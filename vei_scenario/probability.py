"""``estimate_probability``: P(collision) or P(near miss) under a stochastic ParameterValueDistribution,
with a 95 % confidence interval, by crude Monte Carlo and by adaptive importance sampling.

Why two estimators: the failures of a collision-avoidance planner are rare and narrow (the case study's
planner fails in TimeShift windows 0.03-0.07 s wide), so crude Monte Carlo needs millions of runs for a
tight interval. The rare-event estimator learns where the failures are and samples there more often:

1. *Levels* (a cross-entropy scheme with a kernel proposal): draw from the current proposal, score each
   run with a robustness value (the minimum box gap, negative on contact: ``-(1 + impact speed)``; for
   near misses the minimum TTC above the band), keep the best 10 % (or all failures once there are
   enough), and make the next proposal a mixture of the nominal distribution (5 %, a defensive share
   that keeps every weight bounded) and Gaussian kernels around the kept points (half Silverman's
   bandwidth per parameter, as failure sets are narrow and several; a discrete parameter keeps the
   kept point's value with probability 0.95). Stops when the kept points are failures.
2. *Estimate*: a fresh sample from the last proposal, each failure weighted by f(x)/g(x) (nominal over
   proposal density); the interval from the weights' standard error. The level runs are not reused,
   so the estimate is unbiased.

The nominal densities follow the distribution file: normal, log-normal and uniform (truncated to their
``Range``), histograms (piecewise uniform), probability sets and Poisson (discrete). Runs go through
the compiled kernel when the scenario is vei-compiled (thousands per second), else the interpreter.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from vei_scenario.errors import VeiInputError

Z95 = 1.959963984540054
#: collision: with the ego moving at the first contact (speed > 0.1 m/s), a failure of the system that
#: drives it; collision_any: every contact; near-miss: no contact, the minimum TTC within the band.
TARGETS = ("collision", "collision_any", "near-miss")
#: Share of the nominal distribution in every proposal (defensive importance sampling).
DEFENSIVE = 0.05
#: A discrete parameter keeps the value of the kernel's centre with this probability.
KEEP_DISCRETE = 0.95


@dataclass
class Dimension:
    """One stochastic parameter: ``kind`` normal / lognormal / uniform / histogram (continuous) or
    set / poisson (discrete)."""

    name: str
    kind: str
    args: dict
    low: float = -math.inf
    high: float = math.inf
    values: list[str] = field(default_factory=list)  # discrete values (set)
    weights: np.ndarray | None = None  # their probabilities

    @property
    def discrete(self) -> bool:
        return self.kind in ("set", "poisson")

    # --- the nominal distribution (truncated to [low, high]) -------------------------------------
    def _scipy(self):
        from scipy import stats

        a = self.args
        if self.kind == "normal":
            return stats.norm(a["mean"], math.sqrt(a["variance"]))
        if self.kind == "lognormal":
            s2 = math.log(1 + a["variance"] / (a["mean"] ** 2))
            return stats.lognorm(math.sqrt(s2), scale=math.exp(math.log(a["mean"]) - s2 / 2))
        if self.kind == "uniform":
            return stats.uniform(self.low, self.high - self.low)
        return None

    def sample(self, rng: np.random.Generator, n: int) -> np.ndarray:
        if self.kind == "set":
            return rng.choice(len(self.values), size=n, p=self.weights).astype(float)
        if self.kind == "poisson":
            out = rng.poisson(self.args["mean"], size=n).astype(float)
            bad = (out < self.low) | (out > self.high)
            while bad.any():  # truncation by rejection
                out[bad] = rng.poisson(self.args["mean"], size=int(bad.sum()))
                bad = (out < self.low) | (out > self.high)
            return out
        if self.kind == "histogram":
            edges, probs = self.args["bins"], self.weights
            k = rng.choice(len(probs), size=n, p=probs)
            return rng.uniform(edges[k, 0], edges[k, 1])
        dist = self._scipy()
        lo, hi = dist.cdf(self.low), dist.cdf(self.high)
        return dist.ppf(rng.uniform(lo, hi, size=n))

    def pdf(self, x: np.ndarray) -> np.ndarray:
        """Nominal density (continuous) or probability (discrete) of ``x``."""
        if self.kind == "set":
            return self.weights[x.astype(int)]
        if self.kind == "poisson":
            from scipy import stats

            d = stats.poisson(self.args["mean"])
            mass = d.cdf(self.high) - d.cdf(self.low - 1) if math.isfinite(self.low) else d.cdf(self.high)
            inside = (x >= self.low) & (x <= self.high)
            return np.where(inside, d.pmf(x) / mass, 0.0)
        if self.kind == "histogram":
            edges, probs = self.args["bins"], self.weights
            out = np.zeros_like(x, dtype=float)
            for (a, b), p in zip(edges, probs):
                if b > a:
                    out += np.where((x >= a) & (x < b), p / (b - a), 0.0)
            return out
        dist = self._scipy()
        mass = dist.cdf(self.high) - dist.cdf(self.low)
        inside = (x >= self.low) & (x <= self.high)
        return np.where(inside, dist.pdf(x) / mass, 0.0)

    def text(self, x: float) -> str:
        if self.kind == "set":
            return self.values[int(x)]
        if self.kind == "poisson":
            return str(int(x))
        return repr(round(float(x), 9))


def read_stochastic(path: str | Path, declared: dict[str, str]) -> list[Dimension]:
    """The stochastic parameters of a ParameterValueDistribution file, as densities."""
    from vei_scenario.openscenario.numeric_attributes import check_numbers
    from vei_scenario.safe_xml import float_attribute, parse_xml

    path = Path(path)
    root = parse_xml(path).getroot()
    sto = root.find("ParameterValueDistribution/Stochastic")
    if root.tag != "OpenSCENARIO" or sto is None:
        det = root.find("ParameterValueDistribution/Deterministic")
        hint = (
            f" (line {det.sourceline}: <Deterministic> lists values; a probability needs densities: a <Stochastic> "
            'with a <StochasticDistribution parameterName="..."> per parameter, e.g. a <NormalDistribution> with '
            "a <Range>; vei compile --stochastic writes one beside the scenario)"
            if det is not None
            else ""
        )
        raise VeiInputError(path, f"line {root.sourceline}", "not a stochastic ParameterValueDistribution" + hint)
    check_numbers(path, root)
    dims = []
    for d in sto.iterfind("StochasticDistribution"):
        name = d.get("parameterName")
        if name not in declared:
            raise VeiInputError(path, f"line {d.sourceline}", f"varies {name!r}, which the scenario does not declare")
        kind_el = next((c for c in d if isinstance(c.tag, str)), None)
        if kind_el is None:
            raise VeiInputError(path, f"line {d.sourceline}", "an empty StochasticDistribution")
        tag = kind_el.tag
        rng_el = kind_el.find("Range")
        low, high = (-math.inf, math.inf)
        if rng_el is not None:
            low, high = float_attribute(path, rng_el, "lowerLimit"), float_attribute(path, rng_el, "upperLimit")
            if high < low:
                raise VeiInputError(path, f"line {rng_el.sourceline}", "Range upperLimit is below lowerLimit")
        where = f"line {kind_el.sourceline}"
        if tag in ("NormalDistribution", "LogNormalDistribution"):
            mean, var = float_attribute(path, kind_el, "expectedValue"), float_attribute(path, kind_el, "variance")
            if var <= 0 or (tag == "LogNormalDistribution" and mean <= 0):
                raise VeiInputError(path, where, "needs a positive variance (and a positive mean for a log-normal)")
            kind = "normal" if tag == "NormalDistribution" else "lognormal"
            dims.append(Dimension(name, kind, {"mean": mean, "variance": var}, low, high))
        elif tag == "UniformDistribution":
            if rng_el is None or high <= low:
                raise VeiInputError(path, where, "a UniformDistribution needs a Range of positive width")
            dims.append(Dimension(name, "uniform", {}, low, high))
        elif tag == "PoissonDistribution":
            mean = float_attribute(path, kind_el, "expectedValue")
            if not 0 < mean <= 1e6:
                raise VeiInputError(path, where, "a Poisson expectedValue must be in (0, 1e6]")
            dims.append(Dimension(name, "poisson", {"mean": mean}, low, high))
        elif tag == "ProbabilityDistributionSet":
            elems = list(kind_el.iterfind("Element"))
            w = np.array([float_attribute(path, e, "weight") for e in elems])
            if not elems or np.any(w < 0) or w.sum() <= 0:
                raise VeiInputError(path, where, "weights must be non-negative and not all zero")
            dims.append(Dimension(name, "set", {}, values=[e.get("value") for e in elems], weights=w / w.sum()))
        elif tag == "Histogram":
            bins = list(kind_el.iterfind("Bin"))
            w = np.array([float_attribute(path, b, "weight") for b in bins])
            edges = []
            for b in bins:
                r = b.find("Range")
                if r is None:
                    raise VeiInputError(path, f"line {b.sourceline}", "a Bin needs a Range")
                edges.append((float_attribute(path, r, "lowerLimit"), float_attribute(path, r, "upperLimit")))
            if not bins or np.any(w < 0) or w.sum() <= 0:
                raise VeiInputError(path, where, "bin weights must be non-negative and not all zero")
            dims.append(Dimension(name, "histogram", {"bins": np.array(edges)}, weights=w / w.sum()))
        else:
            raise VeiInputError(path, where, f"<{tag}> is not supported for probability estimates")
    if not dims:
        raise VeiInputError(path, f"line {sto.sourceline}", "no StochasticDistribution")
    return dims


class Proposal:
    """Nominal (``centres`` None) or defensive mixture of the nominal and kernels around ``centres``."""

    def __init__(self, dims: list[Dimension], centres: np.ndarray | None = None) -> None:
        self.dims, self.centres = dims, centres
        self.cont = [k for k, d in enumerate(dims) if not d.discrete]
        self.disc = [k for k, d in enumerate(dims) if d.discrete]
        if centres is not None:
            m, q = len(centres), max(1, len(self.cont))
            self.h = np.ones(len(dims))
            for k in self.cont:
                spread = float(np.std(centres[:, k]))
                scale = spread if spread > 0 else 1e-3 * max(1.0, abs(float(centres[0, k])))
                # half of Silverman's rule: the failure sets are narrow and several (multi-modal)
                self.h[k] = max(0.5 * scale * (4.0 / ((q + 2) * m)) ** (1.0 / (q + 4)), 1e-6)

    def nominal_pdf(self, x: np.ndarray) -> np.ndarray:
        out = np.ones(len(x))
        for k, d in enumerate(self.dims):
            out *= d.pdf(x[:, k])
        return out

    def sample(self, rng: np.random.Generator, n: int) -> np.ndarray:
        x = np.column_stack([d.sample(rng, n) for d in self.dims])
        if self.centres is None:
            return x
        use = rng.random(n) >= DEFENSIVE
        j = rng.integers(0, len(self.centres), size=int(use.sum()))
        c = self.centres[j]
        for k in self.cont:
            x[use, k] = c[:, k] + self.h[k] * rng.standard_normal(len(j))
        for k in self.disc:
            keep = rng.random(len(j)) < KEEP_DISCRETE
            x[np.flatnonzero(use)[keep], k] = c[keep, k]
        return x

    def pdf(self, x: np.ndarray) -> np.ndarray:
        f = self.nominal_pdf(x)
        if self.centres is None:
            return f
        kern = np.ones((len(x), len(self.centres)))
        for k in self.cont:
            z = (x[:, k][:, None] - self.centres[None, :, k]) / self.h[k]
            kern *= np.exp(-0.5 * z * z) / (self.h[k] * math.sqrt(2 * math.pi))
        for k in self.disc:
            same = x[:, k][:, None] == self.centres[None, :, k]
            kern *= KEEP_DISCRETE * same + (1 - KEEP_DISCRETE) * self.dims[k].pdf(x[:, k])[:, None]
        return DEFENSIVE * f + (1 - DEFENSIVE) * kern.mean(axis=1)


@dataclass
class Estimate:
    estimator: str  # "monte-carlo" or "importance-sampling"
    probability: float
    low: float
    high: float
    runs: int
    failures: int
    levels: int = 0
    seed: int = 0  # of the sampling (the whole run draws from one generator)

    @property
    def width(self) -> float:
        return self.high - self.low

    def as_dict(self) -> dict:
        return {
            "estimator": self.estimator,
            "probability": self.probability,
            "ci95": [self.low, self.high],
            "runs": self.runs,
            "failures": self.failures,
            "levels": self.levels,
            "seed": self.seed,
        }


def wilson(k: int, n: int) -> tuple[float, float]:
    """Wilson's 95 % score interval of a binomial proportion (sound at 0 and 1 failures)."""
    if n == 0:
        return 0.0, 1.0
    p = k / n
    den = 1 + Z95 * Z95 / n
    centre = (p + Z95 * Z95 / (2 * n)) / den
    half = Z95 * math.sqrt(p * (1 - p) / n + Z95 * Z95 / (4 * n * n)) / den
    lo = 0.0 if k == 0 else max(0.0, centre - half)  # (exactly: the rounding would leave 1e-19)
    hi = 1.0 if k == n else min(1.0, centre + half)
    return lo, hi


class Evaluator:
    """Runs variants and scores them: failure flags and robustness values (lower is worse)."""

    def __init__(self, scenario: Path, dims: list[Dimension], fixed: dict[str, str], target: str,
                 band: tuple[float, float], dt: float, workers: int | None,
                 controllers: tuple = ()) -> None:  # fmt: skip
        self.scenario, self.dims, self.fixed = str(Path(scenario).resolve()), dims, fixed
        self.controllers = controllers
        self.target, self.band, self.dt, self.workers = target, band, dt, workers
        self.runs = 0

    def __call__(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        from vei_scenario.sweep.evaluate import evaluate_local

        variants = [{**self.fixed, **{d.name: d.text(v) for d, v in zip(self.dims, row)}} for row in x]
        rows = evaluate_local(self.scenario, variants, self.dt, self.workers, controllers=self.controllers)
        self.runs += len(rows)
        fail, rho = np.zeros(len(rows), bool), np.zeros(len(rows))
        for i, r in enumerate(rows):
            if r["status"] != "ok":
                raise VeiInputError(self.scenario, "variant", f"{variants[i]} failed: {r['error']}")
            m = r["metrics"]
            counts = m["collision"] if self.target != "collision" else m["collision_ego_moving"]
            if counts:
                impact = m.get("impact_speed_mps") or 0.0
                fail[i], rho[i] = True, -(1.0 + impact)
            elif self.target == "collision":  # (the ego standing at a contact: on the edge, no failure)
                rho[i] = 0.0 if m["collision"] else m["min_gap_m"]
            elif self.target == "collision_any":
                rho[i] = m["min_gap_m"]
            else:
                ttc = m.get("min_ttc_s")
                fail[i] = ttc is not None and self.band[0] <= ttc <= self.band[1]
                rho[i] = -1.0 if fail[i] else (ttc - self.band[1] if ttc is not None else 1e6)
        if self.target == "near-miss":
            collided = rho < -1.0
            fail[collided], rho[collided] = False, 1e6  # a collision is not a near miss
        return fail, rho


#: Runs evaluated at a time (a million runs' rows at once would not fit in memory).
CHUNK = 50_000


def monte_carlo(evaluate: Evaluator, dims: list[Dimension], runs: int, rng) -> Estimate:
    k, left = 0, runs
    while left > 0:
        n = min(CHUNK, left)
        fail, _ = evaluate(Proposal(dims).sample(rng, n))
        k, left = k + int(fail.sum()), left - n
    lo, hi = wilson(k, runs)
    return Estimate("monte-carlo", k / runs, lo, hi, runs, k)


#: Runs per level of importance sampling's proposal search (fewer when the estimate takes fewer).
LEVEL_RUNS = 2000


def importance_sampling(
    evaluate: Evaluator, dims: list[Dimension], runs: int, rng, level_runs: int | None = None, elite: float = 0.1,
    max_levels: int = 8,
) -> Estimate:  # fmt: skip
    """Adaptive importance sampling: levels of ``level_runs`` (default :data:`LEVEL_RUNS`, at most
    ``runs``: a small estimate, as with a system run in the interpreter, does not pay for levels larger
    than itself) move the proposal towards the failures, then ``runs`` runs from it give the estimate."""
    level_runs = min(LEVEL_RUNS, runs) if level_runs is None else level_runs
    proposal = Proposal(dims)
    start = evaluate.runs
    levels = 0
    while levels < max_levels:
        levels += 1
        x = proposal.sample(rng, level_runs)
        fail, rho = evaluate(x)
        keep = max(20, int(elite * level_runs))
        if fail.sum() >= keep:  # enough failures: kernels around them make the last proposal
            proposal = Proposal(dims, x[fail])
            break
        order = np.argsort(rho, kind="stable")[:keep]
        proposal = Proposal(dims, x[order])
    parts, failures, left = [], 0, runs
    while left > 0:
        n = min(CHUNK, left)
        x = proposal.sample(rng, n)
        fail, _ = evaluate(x)
        with np.errstate(divide="ignore", invalid="ignore"):
            parts.append(np.nan_to_num(np.where(fail, proposal.nominal_pdf(x) / proposal.pdf(x), 0.0)))
        failures, left = failures + int(fail.sum()), left - n
    w = np.concatenate(parts)
    p = float(w.mean())
    se = float(w.std(ddof=1) / math.sqrt(runs)) if runs > 1 else math.inf
    total = evaluate.runs - start
    return Estimate("importance-sampling", p, max(0.0, p - Z95 * se), min(1.0, p + Z95 * se), total,
                    failures, levels)  # fmt: skip


def random_seed(path: str | Path) -> int | None:
    """The ``randomSeed`` of a stochastic distribution file, None when it has none: the seed a run
    takes when none is given, as vei sweep does."""
    from vei_scenario.safe_xml import float_attribute, parse_xml

    path = Path(path)
    sto = parse_xml(path).getroot().find("ParameterValueDistribution/Stochastic")
    if sto is None or sto.get("randomSeed") is None:
        return None
    value = float_attribute(path, sto, "randomSeed")
    if not (value.is_integer() and 0 <= value < 2**63):
        raise VeiInputError(path, f"line {sto.sourceline}", "the random seed must be a non-negative integer")
    return int(value)


def estimate_probability(
    scenario: str | Path,
    dist: str | Path,
    target: str = "collision",
    estimators: tuple[str, ...] = ("monte-carlo", "importance-sampling"),
    runs: int = 20000,
    fixed: dict[str, str] | None = None,
    band: tuple[float, float] = (0.5, 1.5),
    seed: int | None = None,
    dt: float = 0.01,
    workers: int | None = None,
    controllers: tuple = (),
    allow_default_controller: bool = False,
) -> list[Estimate]:
    """P(target) under the stochastic distribution ``dist`` (other parameters from ``fixed`` or their
    defaults), by each of ``estimators``, ``runs`` runs each (plus the levels for importance sampling).
    ``seed`` None: the file's ``randomSeed``, else 0; each estimate records the seed it drew with.
    ``controllers``: the systems under test (:class:`~vei_scenario.sut.ControllerSpec`); a controller the
    scenario names that vei has no model of is refused unless ``allow_default_controller``."""
    from vei_scenario.checks import check_dt, finite
    from vei_scenario.interpreter.document import check_values, load_scenario

    check_dt(dt)
    if target not in TARGETS:
        raise VeiInputError(None, "--target", f"{target!r} is not one of {', '.join(TARGETS)}")
    if not (isinstance(runs, int) and 100 <= runs <= 10_000_000):
        raise VeiInputError(None, "--runs", f"{runs!r} is not a number of runs in 100..10000000")
    for b in band:
        finite(b, "--band")
    doc = load_scenario(scenario)
    dims = read_stochastic(dist, doc.parameter_types)
    if seed is None:
        seed = random_seed(dist)
        seed = 0 if seed is None else seed
    fixed = dict(fixed or {})
    check_values(doc.parameter_types, fixed)
    from vei_scenario.sweep.evaluate import refuse_default_controllers

    refuse_default_controllers(scenario, fixed, dt, tuple(controllers), allow_default_controller)
    evaluate = Evaluator(Path(scenario), dims, fixed, target, band, dt, workers, tuple(controllers))
    rng = np.random.default_rng(seed)
    out = []
    for name in estimators:
        if name == "monte-carlo":
            out.append(monte_carlo(evaluate, dims, runs, rng))
        elif name == "importance-sampling":
            out.append(importance_sampling(evaluate, dims, runs, rng))
        else:
            raise VeiInputError(None, "--estimator", f"{name!r} is not monte-carlo or importance-sampling")
        out[-1].seed = seed
    return out
