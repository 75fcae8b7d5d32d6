"""Uncertainty and sensitivity: Monte Carlo prediction bands and Sobol' indices, on many workers.

A model is any function ``model_fn(**params)`` of named scalar parameters returning a number
(or, for :func:`monte_carlo`, an array of a fixed shape); the uncertain parameters are given as
a mapping from each name to a frozen ``scipy.stats`` distribution, taken as independent.

The samples are pseudo-random draws (``sampling="random"``, each distribution's ``rvs``) or
the points of a scrambled Sobol' or Halton sequence (``"sobol"``, ``"halton"``: quasi-Monte
Carlo, ``scipy.stats.qmc``) sent through each distribution's inverse CDF. Quasi-random points
fill the cube more evenly than random ones: for a smooth model the error of a mean falls
nearly as 1/n instead of 1/√n (for the Ishigami function at n = 1024, 30 times smaller than
plain Monte Carlo's; see benchmarks/bench_ch11_uncertainty.py).

Every sample is drawn in the calling process from ``rng`` before any work is sent out; the
evaluations are then split into batches, each one a future, and gathered in their original
order. The answer therefore depends on the seed only: the same seed gives the same numbers,
bit for bit, on one worker, on two, on a pool of threads or on a cluster of many machines. A
``LocalCluster`` with one process per core is started (and closed) by the call when no
``client`` is given; a ``concurrent.futures`` executor (``ThreadPoolExecutor``,
``ProcessPoolExecutor``), a ``distributed.Client``, a scheduler address or a cluster object
(``LocalCluster``, a dask-jobqueue ``SLURMCluster``...) runs the same call elsewhere.

In a script, call these under ``if __name__ == "__main__":``: the worker processes are
started by spawning, and each imports the script that started them.

Processes, not threads, are the default workers: a model written in Python holds the GIL, so
threads would take turns on it, while processes compute side by side (the models are sent to
them by cloudpickle, so a lambda or a function defined in a notebook is fine). Threads serve a
model that spends its time in numpy or compiled code, which releases the GIL.

The indices themselves are ``scipy.stats.sobol_indices``'s (the same two estimators), given
the outputs computed here; see :func:`sobol_indices` for where raildyn's own sums remain. SALib
is not used: its Sobol' analysis is the same two estimators on one in-memory matrix, and what
this module needs around them is what SALib does not do either (draws from any scipy
distribution by a seed, split into futures, gathered in order); it would add a dependency (with
pandas, multiprocess and dill) for the two sums.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.validation import _cluster, _sampling, _sobol

__all__ = ["MonteCarloResult", "SobolResult", "monte_carlo", "sobol_indices"]

#: Most model evaluations one call may ask for (memory for the samples and outputs).
_MAX_EVALUATIONS = 10**8
#: Most workers a LocalCluster started by the call may have (it runs on this one machine).
_MAX_WORKERS = 64


# --------------------------------------------------------------------------- results


@dataclass(frozen=True)
class MonteCarloResult(Tabular):
    """A model's output over samples of its uncertain parameters, and its prediction bands.

    Attributes
    ----------
    names : tuple of str
        The uncertain parameters, in the order of the columns of ``samples``.
    samples : ndarray, shape (n, d)
        The parameter values of each evaluation (each in the unit of its parameter).
    outputs : ndarray, shape (n, ...)
        The model's output for each sample (in the model's unit).
    mean : ndarray, shape (...)
        Sample mean of the outputs.
    std : ndarray, shape (...)
        Sample standard deviation of the outputs (ddof = 1).
    percentiles : ndarray, shape (p,)
        The percentiles of the bands, in [0, 100], increasing.
    bands : ndarray, shape (p, ...)
        The outputs' percentiles (``numpy.percentile``, linear interpolation).
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units;
    # a row per evaluation; the statistics over them (mean, std, bands) are no columns.
    _columns = (("samples", "unit of its parameter"), ("outputs", "model's unit"))
    _labels = (("samples", "names"),)

    names: tuple
    samples: np.ndarray
    outputs: np.ndarray
    mean: np.ndarray
    std: np.ndarray
    percentiles: np.ndarray
    bands: np.ndarray

    def __post_init__(self):
        _checks.strings("names", self.names, unique=True)
        _checks.fields(self)
        n, d = np.shape(self.samples) if np.ndim(self.samples) == 2 else (None, None)
        if d != len(self.names):
            raise ValueError(
                f"samples must have shape (n, {len(self.names)}) (one column per name), "
                f"got shape {np.shape(self.samples)}"
            )
        shape = np.shape(self.outputs)
        if not shape or shape[0] != n:
            raise ValueError(f"outputs must have {n} rows (one per sample), got shape {shape}")
        for field in ("mean", "std"):
            if np.shape(getattr(self, field)) != shape[1:]:
                raise ValueError(
                    f"{field} must have the shape of one output {shape[1:]}, "
                    f"got {np.shape(getattr(self, field))}"
                )
        _checks.array("std", self.std, low=0.0)
        p = _percentiles("percentiles", self.percentiles)
        if np.shape(self.bands) != (p.size, *shape[1:]):
            raise ValueError(
                f"bands must have shape {(p.size, *shape[1:])} (one row per percentile), "
                f"got {np.shape(self.bands)}"
            )

    def plot(self, ax=None, *, x=None, label: str = "") -> dict:
        """Draw the spread of the output: a histogram for a scalar, a band for a curve.

        A scalar output gets the histogram of its samples (as a density) with a vertical
        line at each percentile; a 1-D output gets its median (or middle percentile) against
        ``x`` and the band between the first and the last percentile.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        x : array_like, shape (m,), optional
            Abscissa of a 1-D output of m values (default: 0, 1, ..., m − 1).
        label : str
            Name (and unit) of the output, for the axis.

        Returns
        -------
        dict
            The artists: ``hist`` (the bar patches) and ``percentiles`` (the lines) for a
            scalar; ``band`` and ``line`` for a curve.
        """
        import matplotlib

        from raildyn import plots

        if self.outputs.ndim > 2:
            raise ValueError(
                f"plot draws a scalar or a 1-D output; this result's outputs have shape "
                f"{self.outputs.shape[1:]} per sample"
            )
        if self.outputs.ndim == 1 and x is not None:
            raise ValueError(
                f"x is the abscissa of a 1-D output; this result's output is a scalar, got x = {x!r}"
            )
        with matplotlib.rc_context(plots.STYLE):
            ax = plots.axes_or_new(ax)
            if self.outputs.ndim == 1:
                _, _, bars = ax.hist(
                    self.outputs, bins="auto", density=True, color=plots.COLORS[0], alpha=0.6
                )
                lines = [
                    ax.axvline(b, color=plots.COLORS[1], ls="--", lw=1.0, label=f"{p:g} %")
                    for p, b in zip(self.percentiles, self.bands, strict=True)
                ]
                ax.set_xlabel(label or "output")
                ax.set_ylabel("probability density")
                ax.legend()
                return {"hist": bars, "percentiles": lines}
            m = self.outputs.shape[1]
            xs = np.arange(m, dtype=float) if x is None else _checks.array("x", x, shape=(m,))
            mid = self.bands[len(self.bands) // 2]
            band = ax.fill_between(
                xs,
                self.bands[0],
                self.bands[-1],
                color=plots.COLORS[0],
                alpha=0.25,
                label=f"{self.percentiles[0]:g}–{self.percentiles[-1]:g} %",
            )
            (line,) = ax.plot(
                xs, mid, color=plots.COLORS[0], label=f"{self.percentiles[len(self.bands) // 2]:g} %"
            )
            ax.set_ylabel(label or "output")
            ax.legend()
            return {"band": band, "line": line}


@dataclass(frozen=True)
class SobolResult(Tabular):
    """Sobol' first-order and total sensitivity indices with bootstrap confidence intervals.

    Attributes
    ----------
    names : tuple of str
        The parameters, in the order of the indices.
    first_order : ndarray, shape (d,)
        First-order indices S_i: the share of the output's variance that the parameter
        explains alone (dimensionless; the estimate may dip slightly below 0).
    total : ndarray, shape (d,)
        Total indices S_Ti: the share it explains with all its interactions (S_Ti ≥ S_i).
    first_order_interval : ndarray, shape (d, 2)
        Lower and upper bootstrap percentile bounds of each S_i.
    total_interval : ndarray, shape (d, 2)
        Lower and upper bootstrap percentile bounds of each S_Ti.
    confidence : float
        Confidence level of the intervals, in (0, 1).
    samples : int
        N, the rows of each of the two base samples (the model ran N (d + 2) times).
    variance : float
        The output's variance over the base samples (the model's unit squared).
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("names", "-"), ("first_order", "-"), ("total", "-"), ("first_order_interval", "-"),
        ("total_interval", "-"),
    )  # fmt: skip
    _scalars = (("confidence", "-"), ("samples", "-"), ("variance", "model's unit squared"))

    names: tuple
    first_order: np.ndarray
    total: np.ndarray
    first_order_interval: np.ndarray
    total_interval: np.ndarray
    confidence: float
    samples: int
    variance: float

    def __post_init__(self):
        d = len(_checks.strings("names", self.names, unique=True))
        _checks.fields(self)
        for field, shape in (
            ("first_order", (d,)),
            ("total", (d,)),
            ("first_order_interval", (d, 2)),
            ("total_interval", (d, 2)),
        ):
            _checks.array(field, getattr(self, field), shape=shape)
        _checks.array("total", self.total, low=0.0)  # Jansen's estimator: a mean of squares
        for field in ("first_order_interval", "total_interval"):
            iv = getattr(self, field)
            if np.any(iv[:, 0] > iv[:, 1]):
                i = int(np.flatnonzero(iv[:, 0] > iv[:, 1])[0])
                raise ValueError(f"{field} must hold (lower, upper) pairs, got {iv[i].tolist()} in row {i}")
        _checks.scalar("confidence", self.confidence, low=0.0, high=1.0, low_open=True, high_open=True)
        _checks.integer("samples", self.samples, low=2)
        _checks.positive("variance", self.variance)

    def plot(self, ax=None) -> dict:
        """Bar chart of the first-order and total indices of each parameter, with their intervals.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.

        Returns
        -------
        dict
            The artists: ``first_order`` and ``total`` (each a ``BarContainer``).
        """
        import matplotlib

        from raildyn import plots

        with matplotlib.rc_context(plots.STYLE):
            ax = plots.axes_or_new(ax)
            pos = np.arange(len(self.names), dtype=float)
            w = 0.38
            drawn = {}
            for shift, key, values, interval, colour, text in (
                (-w / 2, "first_order", self.first_order, self.first_order_interval, plots.COLORS[0],
                 "first order $S_i$"),
                (w / 2, "total", self.total, self.total_interval, plots.COLORS[1], "total $S_{Ti}$"),
            ):  # fmt: skip
                err = np.abs(np.vstack([values - interval[:, 0], interval[:, 1] - values]))
                drawn[key] = ax.bar(pos + shift, values, w, yerr=err, color=colour, capsize=3, label=text)
            ax.set_xticks(pos, self.names)
            ax.set_ylabel(f"Sobol' index ({100 * self.confidence:g} % interval)")
            ax.axhline(0.0, color="0.3", lw=0.8)
            ax.legend()
            return drawn


# --------------------------------------------------------------------------- the two analyses


def monte_carlo(
    model_fn: Callable,
    distributions: Mapping,
    samples: int,
    *,
    rng=None,
    sampling: str = "random",
    client=None,
    workers: int | None = None,
    percentiles=(2.5, 50.0, 97.5),
    batch: int | None = None,
    vectorized: bool = False,
) -> MonteCarloResult:
    """Monte Carlo propagation: the model's output over samples of its parameters, with bands.

    Draws ``samples`` values of each parameter from its distribution (pseudo-random, or
    quasi-random points of a scrambled Sobol' or Halton sequence), evaluates the model at
    each sample on the workers (in batches, gathered in order) and returns the outputs with
    their mean, standard deviation and percentiles. The samples come from ``rng`` in this
    process before any evaluation, so the answer is the same whatever runs them.

    Parameters
    ----------
    model_fn : callable
        ``model_fn(**params)`` returns a number or an array of one fixed shape (finite); each
        name of ``distributions`` must be one of its parameters, and it must be picklable
        by cloudpickle (a lambda or a notebook function is). Called with one float per
        parameter, or with one array per parameter (the batch's values) when ``vectorized``.
    distributions : mapping of str to scipy.stats frozen distribution
        Each uncertain parameter's distribution (anything with ``rvs(size, random_state)``,
        and a ``ppf`` for quasi-random sampling), taken as independent, e.g.
        ``{"k": scipy.stats.uniform(0.9e6, 0.2e6)}``.
    samples : int
        Number of samples n, in [2, 10⁸]; a power of two for ``sampling="sobol"``.
    rng : numpy.random.Generator, int or None
        Source of the draws, or of the scrambling of a quasi-random sequence (a seed for a
        reproducible run).
    sampling : {"random", "sobol", "halton"}
        ``"random"``: independent draws by each distribution's ``rvs``. ``"sobol"``: a
        scrambled Sobol' sequence (``scipy.stats.qmc.Sobol``) of n = 2^m points, each
        coordinate sent through its distribution's ``ppf``; another n is refused, because
        the points are balanced over powers of two only. ``"halton"``: a scrambled Halton
        sequence (``scipy.stats.qmc.Halton``), any n.
    client : concurrent.futures.Executor, distributed.Client, str, cluster or None
        Where to run: None starts a ``LocalCluster`` of ``workers`` processes for this call
        and closes it after; an executor (``ThreadPoolExecutor``, ``ProcessPoolExecutor``,
        any ``concurrent.futures.Executor``) or a ``distributed.Client`` is used as it is and
        left open; a string is a scheduler address (``"tcp://host:8786"``); a cluster object
        (``LocalCluster``, a dask-jobqueue cluster) is connected to for the call.
    workers : int or None
        Worker processes of the ``LocalCluster`` started when ``client`` is None, in [1, 64];
        None: one per core this process may use (at most 64).
    percentiles : array_like, shape (p,)
        Percentiles of the bands, in [0, 100], strictly increasing (default: the median and
        the 95 % band).
    batch : int or None
        Evaluations per task (≥ 1); None splits the work into four near-equal batches per
        worker (at least 16 in all), enough to balance the load and move the progress bar,
        few enough that the cost of each task stays small.
    vectorized : bool
        Whether ``model_fn`` takes arrays (one value per evaluation of the batch) and returns
        an array with one row per evaluation.

    Returns
    -------
    MonteCarloResult
        Samples, outputs, mean, standard deviation and bands.

    Raises
    ------
    ValueError
        For a parameter name ``model_fn`` does not take, a distribution that draws
        non-finite values, a ``sampling`` not in the list or a number of samples it does not
        take, or a model output that is not finite (the message names the sample and its
        parameter values) or changes shape.

    Notes
    -----
    The bands are sample percentiles: with n draws the 2.5 % point is estimated from about
    0.025 n outputs below it, so a 95 % band wants n in the thousands. With random draws the
    mean's standard error is std / √n; quasi-random points are not independent, and for a
    smooth model their mean is much closer than that (its error is measured by repeating the
    study with other seeds, each scrambling the sequence afresh).

    Examples
    --------
    >>> from scipy import stats
    >>> from distributed import Client
    >>> with Client(n_workers=1, processes=False, dashboard_address=":0") as client:
    ...     mc = monte_carlo(lambda k, m: (k / m) ** 0.5, {"k": stats.norm(1e6, 1e5),
    ...                      "m": stats.uniform(900, 200)}, 400, rng=1, client=client)
    >>> mc.outputs.shape, bool(30 < mc.mean < 34)
    ((400,), True)

    The same study on 256 points of a scrambled Sobol' sequence, on a pool of threads:

    >>> from concurrent.futures import ThreadPoolExecutor
    >>> with ThreadPoolExecutor(2) as pool:
    ...     qmc = monte_carlo(lambda k, m: (k / m) ** 0.5, {"k": stats.norm(1e6, 1e5),
    ...                       "m": stats.uniform(900, 200)}, 256, rng=1, sampling="sobol", client=pool)
    >>> round(float(qmc.mean), 1)
    31.6
    """
    names, gen, n_workers, chunk = _common(
        model_fn, distributions, samples, rng, sampling, client, workers, batch, vectorized
    )
    p = _percentiles("percentiles", percentiles)
    X = _sampling.draw(distributions, names, samples, gen, sampling)
    Y = _cluster.evaluate_all(model_fn, names, X, client, n_workers, chunk, vectorized, "Monte Carlo")
    return MonteCarloResult(
        names,
        X,
        Y,
        Y.mean(axis=0),
        Y.std(axis=0, ddof=1),
        p,
        np.percentile(Y, p, axis=0),
    )


def sobol_indices(
    model_fn: Callable,
    distributions: Mapping,
    samples: int,
    *,
    rng=None,
    sampling: str = "random",
    client=None,
    workers: int | None = None,
    bootstrap: int = 1000,
    confidence: float = 0.95,
    batch: int | None = None,
    vectorized: bool = False,
) -> SobolResult:
    """Sobol' first-order and total sensitivity indices of a scalar model, with bootstrap intervals.

    Two independent N × d samples A and B are drawn (pseudo-random, or the two halves of
    one scrambled quasi-random sequence of dimension 2d, as Saltelli et al. 2010, section 5,
    make them); for each parameter i the matrix A_B⁽ⁱ⁾ is A with its column i taken from B.
    The model runs on A, B and the d matrices A_B⁽ⁱ⁾, N (d + 2) times in all, on the
    workers. With f₀ and σ_Y² the mean and the
    variance of f over A and B together, the first-order index uses Saltelli's estimator
    and the total index Jansen's (Jansen 1999), both as Saltelli et al. (2010, Table 2) list them
    (derived in notebook 11 from the law of total variance):

    S_i = (1/N) Σ_j (f(B)_j − f₀) (f(A_B⁽ⁱ⁾)_j − f(A)_j) / σ_Y²,
    S_Ti = (1/2N) Σ_j (f(A)_j − f(A_B⁽ⁱ⁾)_j)² / σ_Y².

    Saltelli's estimator is written with f(B) itself; subtracting f₀ leaves its expectation
    unchanged and removes the noise an output's mean adds to it (scipy's and SALib's analyses
    centre their outputs too), so the indices of f and of f + c agree.

    The two sums are ``scipy.stats.sobol_indices``'s (its ``saltelli_2010`` method), handed
    the outputs computed here, whenever N is a power of two. raildyn keeps its own few lines
    of numpy for what scipy's cannot do: scipy refuses any other N, even with the outputs
    given, and its callable form evaluates the model on all samples at once in this process
    (no batches, no workers, no progress). The intervals are raildyn's too: scipy's
    bootstrap (BCa) takes no seed, so its intervals would change from run to run.

    The intervals are bootstrap percentile intervals over the N rows (Efron & Tibshirani
    1993, ch. 13), resampled ``bootstrap`` times with draws from ``rng`` after the samples.
    They treat the rows as independent: with quasi-random samples, which are not, they
    overstate the error.

    Parameters
    ----------
    model_fn : callable
        ``model_fn(**params)`` returns one finite number; see :func:`monte_carlo`.
    distributions : mapping of str to scipy.stats frozen distribution
        Each parameter's distribution; the indices assume independent parameters.
    samples : int
        N, the rows of each base sample, in [2, 10⁷]; a power of two for
        ``sampling="sobol"``. The estimators' standard error falls as 1/√N with random
        samples; for the Ishigami function it is 0.004 to 0.017 at N = 8192.
    rng : numpy.random.Generator, int or None
        Source of the samples and of the bootstrap (a seed for a reproducible run).
    sampling : {"random", "sobol", "halton"}
        How A and B are drawn; see :func:`monte_carlo`.
    client : concurrent.futures.Executor, distributed.Client, str, cluster or None
        Where to run; see :func:`monte_carlo`.
    workers : int or None
        Worker processes of the ``LocalCluster`` started when ``client`` is None, in [1, 64];
        None: one per core.
    bootstrap : int
        Bootstrap resamples for the intervals, in [10, 10⁵].
    confidence : float
        Confidence level of the intervals, in (0, 1).
    batch : int or None
        Evaluations per task (≥ 1); None: see :func:`monte_carlo`.
    vectorized : bool
        Whether ``model_fn`` takes and returns arrays; see :func:`monte_carlo`.

    Returns
    -------
    SobolResult
        S_i, S_Ti, their intervals and the output's variance.

    Raises
    ------
    ValueError
        As :func:`monte_carlo`; also for an output that is not a single number, or one that
        does not vary over the samples (the indices divide by its variance).

    Examples
    --------
    >>> from scipy import stats
    >>> from distributed import Client
    >>> with Client(n_workers=1, processes=False, dashboard_address=":0") as client:
    ...     s = sobol_indices(lambda x, y: x + 2 * y, {"x": stats.norm(), "y": stats.norm()},
    ...                       2000, rng=3, client=client, bootstrap=100)
    >>> s.first_order.round(1).tolist(), s.total.round(1).tolist()  # 1/5 and 4/5
    ([0.2, 0.8], [0.2, 0.8])
    """
    names, gen, n_workers, chunk = _common(
        model_fn, distributions, samples, rng, sampling, client, workers, batch, vectorized, sobol=True
    )
    d = len(names)
    resamples = _checks.integer("bootstrap", bootstrap, low=10, high=10**5)
    level = _checks.scalar("confidence", confidence, low=0.0, high=1.0, low_open=True, high_open=True)
    N = samples
    AB = _sampling.draw(distributions, names, N, gen, sampling, blocks=2)
    A, B = AB[:, :d], AB[:, d:]
    stacked = [A, B]
    for i in range(d):
        ABi = A.copy()
        ABi[:, i] = B[:, i]
        stacked.append(ABi)
    X = np.concatenate(stacked)
    Y = _cluster.evaluate_all(
        model_fn, names, X, client, n_workers, chunk, vectorized, "Sobol' indices", scalar=True
    )
    fA, fB, fAB = Y[:N], Y[N : 2 * N], Y[2 * N :].reshape(d, N)
    variance = float(np.var(Y[: 2 * N]))
    if not variance > 0.0:
        raise ValueError(
            f"model_fn's output does not vary over the {2 * N} base samples (variance {variance!r}): "
            "its Sobol' indices are undefined"
        )
    first, total = _sobol.indices(fA, fB, fAB)
    first_interval, total_interval = _sobol.bootstrap_intervals(fA, fB, fAB, gen, resamples, level)
    return SobolResult(names, first, total, first_interval, total_interval, level, N, variance)


# --------------------------------------------------------------------------- checks


def _common(
    model_fn, distributions, samples, rng, sampling, client, workers, batch, vectorized, *, sobol=False
):
    """Check what both analyses take, before anything is drawn or sent; return the names and the rest."""
    _checks.function("model_fn", model_fn)
    names = _names(distributions)
    _check_signature(model_fn, names)
    per_sample = len(names) + 2 if sobol else 1  # model runs per sample: N (d + 2) for Sobol' indices
    _checks.integer("samples", samples, low=2, high=_MAX_EVALUATIONS // per_sample)
    _sampling.check(sampling, distributions, names, samples)
    gen = _checks.generator(rng)
    if workers is None:
        workers = min(_cluster.machine_cores(), _MAX_WORKERS)
    n_workers = _checks.integer("workers", workers, low=1, high=_MAX_WORKERS)
    chunk = None if batch is None else _checks.integer("batch", batch, low=1)
    _checks.flag("vectorized", vectorized)
    _cluster.check_client(client)
    return names, gen, n_workers, chunk


def _names(distributions) -> tuple:
    """The parameter names of ``distributions``, each value checked to be a distribution."""
    _checks.instance("distributions", distributions, Mapping, "mapping of parameter names to distributions")
    if not distributions:
        raise ValueError("distributions must name at least one parameter, got an empty mapping")
    for name, dist in distributions.items():
        if not isinstance(name, str) or not name.isidentifier():
            raise ValueError(
                f"distributions must be keyed by parameter names (Python identifiers), got the key {name!r}"
            )
        if not callable(getattr(dist, "rvs", None)):
            raise TypeError(
                f"distributions[{name!r}] must be a frozen scipy.stats distribution (with rvs), "
                f"got {dist!r:.80} of type {type(dist).__name__}"
            )
    return tuple(distributions)


def _check_signature(model_fn, names) -> None:
    """Every name must be a keyword model_fn takes, and every parameter it needs must be named."""
    try:
        params = inspect.signature(model_fn).parameters
    except (TypeError, ValueError):  # a builtin without a signature: its own call will tell
        return
    kinds = {p.kind for p in params.values()}
    if inspect.Parameter.VAR_KEYWORD not in kinds:
        takes = {
            k for k, p in params.items() if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)
        }  # fmt: skip
        unknown = [n for n in names if n not in takes]
        if unknown:
            raise ValueError(
                f"distributions names {unknown}, which model_fn does not take; it takes {sorted(takes)}"
            )
    needed = [
        k
        for k, p in params.items()
        if p.default is inspect.Parameter.empty
        and p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)
        and k not in names
    ]
    if needed:
        raise ValueError(
            f"model_fn needs {needed}, which distributions does not give; give each a distribution "
            "or a default value"
        )


def _percentiles(name, value) -> np.ndarray:
    """A non-empty, strictly increasing 1-D array of percentiles in [0, 100]."""
    p = _checks.increasing(name, np.atleast_1d(_checks.array(name, value)), low=0.0)
    if p[-1] > 100.0:
        raise ValueError(f"{name} must lie in [0, 100], got {p[-1]!r}")
    return p
