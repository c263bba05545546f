"""Adapters that solve roughcontact's force-controlled contact problem in peer codes.

Each adapter takes the same heights array ``z`` as :func:`roughcontact.contact.solve`
and returns, per force, the depth from first touch, the contact set and the
pressure per cell in roughcontact's conventions, so the results can be compared
number for number.

Convention mapping
------------------
roughcontact
    ``z`` is the indenter's shape measured from the undeformed half-space
    towards the indenter; ``depth`` ``d`` is counted from first touch;
    ``u = d − (z − min z)`` on the contact set; pressure ``p`` per square cell
    of side ``Δ = L/n``; ``force = Σ p Δ²``; ``E*`` is the effective modulus.
ContactMechanics 1.8 (with SurfaceTopography)
    The rigid surface has heights ``h`` and the constraint is ``u ≥ h + offset``,
    so ``h = −(z − min z)`` (``max h = 0``) makes ``offset`` equal to ``d``.
    ``FreeFFTElasticHalfSpace(young=E*)``: its ``young`` is the contact
    modulus ``E'`` with ``1/E' = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂``, and its Green's
    function is Love's uniform-pressure-on-a-rectangle solution convolved by a
    zero-padded FFT, the same discrete operator as roughcontact's. Its unknowns
    are pixel forces ``f = p Δ²``; the external force is ``Σ f``.
tamaas 2.9
    ``ModelFactory.registerNonPeriodic(model, "dcfft")`` registers the
    non-periodic Boussinesq operator (Love's kernel with DC-FFT, verified to
    coincide with ContactMechanics' to round-off) and
    ``PolonskyKeerRey.setIntegralOperator("dcfft")`` makes the solver use it.
    ``model_type.basic_2d`` with ``E = E*`` and ``ν = 0`` gives
    ``E* = E/(1 − ν²)``. The surface is ``h = −(z − min z)`` as above;
    ``solve`` takes the mean pressure ``F/L²``; ``model.traction`` is the
    pressure per cell. ``model.displacement`` is the true displacement minus
    the rigid-body offset, so ``d`` is recovered as the mean over the contact
    set of ``K p − model.displacement`` with the solver's own operator ``K``.

Adhesion (:class:`TamaasAdhesionPeer`)
    tamaas 2.9 adds an adhesive interaction only to the Polonsky–Keer–Rey
    solver whose primal variable is the gap (``PolonskyKeerRey.gap``):
    ``addFunctionalTerm`` passes the functional the primal field, so on the
    pressure primal (the one that can take the ``dcfft`` operator) it would
    read pressures as gaps, and the gap primal needs the inverse operator
    (pressure from displacement), which tamaas has for the periodic
    half-space only (``westergaard_dirichlet``). The comparison is therefore
    made on the periodic half-space: tamaas' ``westergaard_neumann`` operator
    (``ũ = 2p̃/(E*|q|)``, ``ũ(0) = 0``) coincides with roughcontact's
    ``PeriodicOperator`` to round-off. With the constraint on the gap too,
    ``solve(ḡ)`` imposes the mean gap ``ḡ`` over the grid; tamaas' gap is
    ``g = u − h`` with ``h = −(z − min z)`` and ``u`` its displacement (rigid
    offset included), roughcontact's ``g = (z − min z) − d + K p`` with
    ``K p`` of zero mean, so the approach ``d`` is imposed by
    ``ḡ = mean(z − min z) − d``. ``MaugisAdhesionFunctional`` with
    ``rho = δ_t`` and ``surface_energy = w`` adds the tension ``w/ρ = σ₀`` on
    every open cell with ``g ≤ ρ`` — the Dugdale law of
    :mod:`roughcontact.bem.cohesive` — and the contact pressure is bounded
    below by ``−σ₀`` by the same Lagrange condition. The pressure is
    ``model.traction`` (compressive positive; round-off of ±10⁻¹³ off the
    contact), the contact the cells with ``g ≤ 10⁻¹²·δ_t``.

Tolerances
----------
roughcontact stops when ``max_c |g| ≤ tol·d`` and ``min_(not c) g ≥ −tol·d``
(``g`` the gap, ``c`` the contact set). ContactMechanics' Bugnicourt solver
stops when the largest projected gap residual is ``≤ gtol``: with
``gtol = tol·d`` that is the same test. Its Polonsky–Keer solver gets
``pentol = tol·d``, ``thermotol = tol`` and ``forcetol = tol·F``. ``d`` is not
known before the solve: it is estimated from a neighbouring solution
(``d₀ (F/F₀)^(2/3)``), or, without one, the solve is repeated warm-started
with the depth just found until the estimate is within a factor 2 of the
result. tamaas' Polonsky–Keer–Rey solver has its own relative error measure
and is given ``tol`` unchanged. With an adhesion functional, its
``computeError()`` called after ``solve`` does not include the functional
(it reads 10–50 on converged states), so :class:`TamaasAdhesionPeer` reads
the error of the last iteration from tamaas' log, and checks each state
against the Dugdale law itself (``law_residual``).

Stiffness
---------
The peers have no tangent stiffness: :func:`load_path` uses the central
difference quotient of Pohrt & Popov (2013), ``k = (F₊ − F₋)/(d₊ − d₋)``
from two extra solves at ``F (1 ± rel_step)``, each warm-started from the
solution at ``F``, and times them separately.
"""

from __future__ import annotations

import contextlib
import dataclasses
import io
import re
import time
from importlib.metadata import PackageNotFoundError, version

import numpy as np

__all__ = [
    "PeerSolution",
    "PeerPoint",
    "ContactMechanicsPeer",
    "TamaasPeer",
    "TamaasAdhesionPeer",
    "AdhesionPeerPath",
    "make_peer",
    "load_path",
    "peer_versions",
    "PEER_NAMES",
]

#: Peer keys accepted by :func:`make_peer`.
PEER_NAMES = ("cm", "tamaas")

#: Iteration cap of every peer solve (far above what converged solves need).
MAX_ITERATIONS = 100_000

#: A warm-started ContactMechanics solution is accepted when its penetration outside
#: the contact set is at most ``ACCEPT·tol·d`` (roughcontact stops at ``tol·d``).
ACCEPT = 10.0


@dataclasses.dataclass(frozen=True, eq=False)
class PeerSolution:
    """One force-controlled solve by a peer, in roughcontact's conventions.

    Attributes
    ----------
    force : float
        Target total force (force unit).
    depth : float
        Rigid-body approach from first touch (length unit).
    pressure : numpy.ndarray
        ``(n, n)`` pressure per cell (force/length²).
    contact : numpy.ndarray
        ``(n, n)`` bool, cells with positive pressure.
    iterations : int
        Iterations of the peer's solver (all passes included).
    seconds : float
        Wall time of the solve, including the recovery of ``depth``.
    """

    force: float
    depth: float
    pressure: np.ndarray
    contact: np.ndarray
    iterations: int
    seconds: float


@dataclasses.dataclass(frozen=True)
class PeerPoint:
    """One point of a load path: the solve at ``force`` and its stiffness.

    Attributes
    ----------
    force, depth : float
        As in :class:`PeerSolution`.
    stiffness : float
        Central difference quotient ``(F₊ − F₋)/(d₊ − d₋)`` (force/length).
    iterations : int
        Iterations of the solve at ``force``.
    stiffness_iterations : int
        Iterations of the two extra solves.
    solve_seconds, stiffness_seconds : float
        Wall times of the solve and of the two extra solves.
    contact_cells : int
        Number of cells in contact at ``force``.
    """

    force: float
    depth: float
    stiffness: float
    iterations: int
    stiffness_iterations: int
    solve_seconds: float
    stiffness_seconds: float
    contact_cells: int


def _peer_heights(heights: np.ndarray) -> np.ndarray:
    """Rigid-surface heights of both peers: ``h = −(z − min z)``, so ``max h = 0``."""
    heights = np.asarray(heights, dtype=float)
    if heights.ndim != 2 or heights.shape[0] != heights.shape[1]:
        raise ValueError(f"heights must be a square 2-D array, got shape {heights.shape}")
    return -(heights - heights.min())


def _depth_estimate(force: float, initial: PeerSolution | None) -> float | None:
    """Hertz-like scaling ``d₀ (F/F₀)^(2/3)`` from a neighbouring solution, if any."""
    if initial is None or initial.depth <= 0:
        return None
    return initial.depth * (force / initial.force) ** (2.0 / 3.0)


class ContactMechanicsPeer:
    """ContactMechanics (SurfaceTopography) on a non-periodic half-space, force-controlled.

    Parameters
    ----------
    heights : array_like, shape (n, n)
        Indenter shape ``z`` in roughcontact's convention.
    length : float
        Side of the grid (length unit).
    e_star : float
        Effective modulus (force/length²).
    tol : float
        roughcontact's tolerance, mapped as in the module docstring.
    solver : {"bugnicourt", "polonsky_keer"}
        ``"bugnicourt"``: NuMPI's constrained conjugate gradients without
        restart (Bugnicourt et al. 2018) on ContactMechanics' dual objective
        (pixel forces as unknowns, ``NonSmoothContactSystem.dual_objective``)
        with the mean pixel force constrained to ``F/n²``. ``"polonsky_keer"``:
        ``ContactMechanics.Optimization.constrained_conjugate_gradients``
        with ``external_force`` (Polonsky & Keer 1999). These are the two
        force-controlled non-periodic solvers of ContactMechanics 1.8; the
        other dual and primal minimisers (``ccg-with-restart``, L-BFGS-B) take
        the offset, not the force.

    Attributes
    ----------
    notices : int
        Lines NuMPI printed during Bugnicourt solves (negative step lengths),
        collected here instead of cluttering the output.
    """

    name = "ContactMechanics"

    def __init__(self, heights, *, length: float, e_star: float, tol: float = 1e-8,
                 solver: str = "polonsky_keer"):
        from ContactMechanics import FreeFFTElasticHalfSpace
        from ContactMechanics.Systems import NonSmoothContactSystem
        from SurfaceTopography import Topography

        if solver not in ("bugnicourt", "polonsky_keer"):
            raise ValueError(f"solver must be 'bugnicourt' or 'polonsky_keer', got {solver!r}")
        self.heights = _peer_heights(heights)
        self.n = self.heights.shape[0]
        self.length = float(length)
        self.e_star = float(e_star)
        self.tol = float(tol)
        self.solver = solver
        self.cell_area = (self.length / self.n) ** 2
        self.substrate = FreeFFTElasticHalfSpace((self.n, self.n), self.e_star,
                                                 (self.length, self.length))
        self.topography = Topography(self.heights, (self.length, self.length))
        self.system = NonSmoothContactSystem(substrate=self.substrate, surface=self.topography)
        self.notices = 0

    def _bugnicourt(self, force: float, pixel_forces: np.ndarray, depth_scale: float):
        from NuMPI.Optimization.CCGWithoutRestart import constrained_conjugate_gradients

        # With offset 0 the dual gradient is u − h, which equals d on the contact set.
        objective = self.system.dual_objective(0.0, gradient=True)
        # NuMPI prints a notice when a step length comes out negative (it
        # happens right after a warm start); collect it instead.
        notices = io.StringIO()
        with contextlib.redirect_stdout(notices):
            result = constrained_conjugate_gradients(
                objective, self.system.dual_hessian_product, x0=pixel_forces,
                mean_val=force / self.n**2, gtol=self.tol * depth_scale, maxiter=MAX_ITERATIONS)
        self.notices += notices.getvalue().count("\n")
        if not result.success:
            raise RuntimeError(f"ContactMechanics (bugnicourt) did not converge: {result.message}")
        pixel_forces = result.x.reshape(self.n, self.n)
        contact = pixel_forces > 0
        depth = float(np.mean(self.system.gradient[contact]))
        return pixel_forces, depth, int(result.nit)

    def _polonsky_keer(self, force: float, pixel_forces: np.ndarray, depth_scale: float):
        from ContactMechanics.Optimization import constrained_conjugate_gradients

        padded = np.zeros(self.substrate.nb_domain_grid_pts)
        padded[: self.n, : self.n] = -pixel_forces    # ContactMechanics: compressive < 0
        result = constrained_conjugate_gradients(
            self.substrate, self.topography, external_force=force, initial_forces=padded,
            pentol=self.tol * depth_scale, forcetol=self.tol * force, thermotol=self.tol,
            maxiter=MAX_ITERATIONS)
        if not result.success:
            raise RuntimeError(f"ContactMechanics (polonsky_keer) did not converge: {result.message}")
        return np.asarray(result.jac), float(result.offset), int(result.nit)

    def _penetration(self, pixel_forces: np.ndarray, depth: float) -> float:
        """Largest penetration outside the contact set, relative to ``depth``: the
        half of roughcontact's stopping test that ContactMechanics does not check."""
        from roughcontact.bem import displacement

        pressure = pixel_forces / self.cell_area
        gap = displacement(pressure, length=self.length, e_star=self.e_star) - self.heights - depth
        return float(-gap[pressure <= 0].min(initial=0.0) / depth)

    def solve(self, force: float, *, initial: PeerSolution | None = None) -> PeerSolution:
        """Solve at total ``force``, warm-started from ``initial`` if given.

        Parameters
        ----------
        force : float
            Total normal force (force unit).
        initial : PeerSolution, optional
            A neighbouring solution; its pressure, scaled to ``force``, is the
            starting point and its depth sets the tolerance scale. A
            warm-started solution that penetrates the indenter outside its
            contact set by more than ``ACCEPT·tol·d`` is discarded and the
            solve repeated from uniform forces (the check's time is counted).

        Returns
        -------
        PeerSolution
        """
        method = self._bugnicourt if self.solver == "bugnicourt" else self._polonsky_keer
        start = time.perf_counter()
        if initial is None:
            pixel_forces = np.full((self.n, self.n), force / self.n**2)
        else:
            pixel_forces = initial.pressure * self.cell_area * (force / initial.force)
        depth_scale = _depth_estimate(force, initial)
        refine = depth_scale is None
        if refine:
            depth_scale = float(-self.heights.min())
        iterations = 0
        while True:
            pixel_forces, depth, spent = method(force, pixel_forces, depth_scale)
            iterations += spent
            if initial is not None and self._penetration(pixel_forces, depth) > ACCEPT * self.tol:
                # ContactMechanics' Polonsky-Keer stops after one iteration when a warm
                # start has a single contact cell (zero step, and its penetration test
                # looks only inside the contact set): start again from uniform forces.
                initial, refine = None, True
                pixel_forces = np.full((self.n, self.n), force / self.n**2)
                depth_scale = float(-self.heights.min())
                continue
            if not refine or depth >= 0.5 * depth_scale:
                break
            depth_scale = depth
        seconds = time.perf_counter() - start
        pressure = pixel_forces / self.cell_area
        return PeerSolution(force=float(force), depth=depth, pressure=pressure,
                            contact=pressure > 0, iterations=iterations, seconds=seconds)


def _tamaas_log(tm, call) -> str:
    """Run *call* with tamaas logging at info level to stderr, captured; return the log text
    (tamaas prints its iteration table there), the previous log level restored."""
    log = io.StringIO()
    level = tm.get_log_level()
    tm.set_log_level(tm.LogLevel.info)
    try:
        with contextlib.redirect_stderr(log):
            call()
    finally:
        tm.set_log_level(level)
    return log.getvalue()


class TamaasPeer:
    """tamaas' Polonsky–Keer–Rey solver on the non-periodic ("dcfft") half-space.

    Parameters
    ----------
    heights : array_like, shape (n, n)
        Indenter shape ``z`` in roughcontact's convention.
    length : float
        Side of the grid (length unit).
    e_star : float
        Effective modulus (force/length²); set as ``E = E*``, ``ν = 0``.
    tol : float
        Tolerance of ``PolonskyKeerRey`` (its own relative error measure).
    """

    name = "tamaas"
    operator_name = "dcfft"
    _last_iteration = re.compile(r"^\s*(\d+)\s+\S+\s+\S+\s*$")

    def __init__(self, heights, *, length: float, e_star: float, tol: float = 1e-8):
        import tamaas as tm

        self._tm = tm
        self.heights = _peer_heights(heights)
        self.n = self.heights.shape[0]
        self.length = float(length)
        self.tol = float(tol)
        self.model = tm.ModelFactory.createModel(tm.model_type.basic_2d,
                                                 [self.length, self.length], [self.n, self.n])
        self.model.E = float(e_star)
        self.model.nu = 0.0
        tm.ModelFactory.registerNonPeriodic(self.model, self.operator_name)
        self.operator = self.model.operators[self.operator_name]
        self.solver = tm.PolonskyKeerRey(self.model, self.heights, self.tol)
        self.solver.setIntegralOperator(self.operator_name)
        self.solver.max_iter = MAX_ITERATIONS

    def _run(self, force: float) -> int:
        """Solve, returning the iteration count that tamaas logs (to stderr) at info level."""
        log = _tamaas_log(self._tm, lambda: self.solver.solve(force / self.length**2))
        lines = [m.group(1) for m in map(self._last_iteration.match, log.splitlines()) if m]
        if not lines:
            raise RuntimeError(f"could not read tamaas' iteration count from its log: {log!r}")
        error = self.solver.computeError()
        if not error <= self.tol:
            raise RuntimeError(f"tamaas did not converge: error {error:g} > tol {self.tol:g}")
        return int(lines[-1])

    def solve(self, force: float, *, initial: PeerSolution | None = None) -> PeerSolution:
        """Solve at total ``force``, warm-started from ``initial`` if given.

        Parameters
        ----------
        force : float
            Total normal force (force unit).
        initial : PeerSolution, optional
            A neighbouring solution; its pressure scaled to ``force`` is the
            starting point. Without it, or where tamaas fails on the warm start
            (a contact of a cell or two), the solve starts from zero pressure.

        Returns
        -------
        PeerSolution
        """
        start = time.perf_counter()
        if initial is None:
            self.model.traction[...] = 0.0
            iterations = self._run(force)
        else:
            self.model.traction[...] = initial.pressure * (force / initial.force)
            try:
                iterations = self._run(force)
            except self._tm.FloatingPointError:
                # tamaas 2.9 computes its error as 0/0 on a warm-started contact of
                # one or two cells; the cold start from zero pressure works there.
                self.model.traction[...] = 0.0
                iterations = self._run(force)
        pressure = np.array(self.model.traction, copy=True)
        contact = pressure > 0
        displacement = np.zeros_like(pressure)
        self.operator(self.model.traction, displacement)
        depth = float(np.mean((displacement - self.model.displacement)[contact]))
        seconds = time.perf_counter() - start
        return PeerSolution(force=float(force), depth=depth, pressure=pressure, contact=contact,
                            iterations=iterations, seconds=seconds)


@dataclasses.dataclass(frozen=True, eq=False)
class AdhesionPeerPath:
    """A displacement-controlled adhesive path solved by a peer, in roughcontact's conventions.

    Attributes
    ----------
    depth, force : numpy.ndarray
        Approach from first touch (length) and total force ``Σ p Δ²`` (negative: tensile).
    contact_cells, zone_cells : numpy.ndarray
        Cells in contact (``g = 0``) and in the cohesive zone (``0 < g ≤ δ_t``).
    iterations : numpy.ndarray
        Iterations of the peer's solver per approach.
    error : numpy.ndarray
        The peer's own error at its last iteration, per approach.
    converged : numpy.ndarray
        Bool per approach: ``error ≤ tol`` within the iteration cap.
    law_residual : numpy.ndarray
        Per approach, the largest violation of the Dugdale law by the returned state, over
        ``σ₀``: ``|p − law(g)|`` on the open cells (``law = −σ₀`` for ``g ≤ δ_t``, 0 beyond) and
        ``−σ₀ − p`` where positive on the contact.
    seconds : numpy.ndarray
        Wall time per approach.
    """

    depth: np.ndarray
    force: np.ndarray
    contact_cells: np.ndarray
    zone_cells: np.ndarray
    iterations: np.ndarray
    error: np.ndarray
    converged: np.ndarray
    law_residual: np.ndarray
    seconds: np.ndarray

    @property
    def pull_off_force(self) -> float:
        """The most tensile force of the path."""
        return float(self.force.min())


class TamaasAdhesionPeer:
    """tamaas' Polonsky–Keer–Rey solver with ``MaugisAdhesionFunctional`` (periodic half-space).

    The conventions are in the module docstring (Adhesion). Each approach is warm-started from
    the previous one: tamaas keeps its gap between calls of ``solve``.

    Parameters
    ----------
    heights : array_like, shape (n, n)
        Indenter shape ``z`` in roughcontact's convention.
    length, e_star : float
        Side of the grid and effective modulus (``E = E*``, ``ν = 0``).
    work_of_adhesion, cohesive_stress : float
        ``w`` and ``σ₀`` of :func:`roughcontact.bem.cohesive.cohesive_path`; ``rho = w/σ₀``.
    tol : float
        Tolerance of ``PolonskyKeerRey`` (its own error measure).
    max_iter : int
        Iteration cap per approach.
    """

    name = "tamaas"
    _log_row = re.compile(r"^\s*(\d+)\s+(\S+)\s+(\S+)\s*$")

    def __init__(self, heights, *, length: float, e_star: float, work_of_adhesion: float,
                 cohesive_stress: float, tol: float = 1e-10, max_iter: int = 10_000):
        import tamaas as tm

        self._tm = tm
        self.surface = _peer_heights(heights)          # h = −(z − min z); kept alive for tamaas
        self.n = self.surface.shape[0]
        self.length = float(length)
        self.tol = float(tol)
        self.sigma = float(cohesive_stress)
        self.range = float(work_of_adhesion) / self.sigma
        self.mean_height = float(-self.surface.mean())
        self.model = tm.ModelFactory.createModel(tm.model_type.basic_2d,
                                                 [self.length, self.length], [self.n, self.n])
        self.model.E = float(e_star)
        self.model.nu = 0.0
        self.solver = tm.PolonskyKeerRey(self.model, self.surface, self.tol,
                                         tm.PolonskyKeerRey.gap, tm.PolonskyKeerRey.gap)
        self.solver.max_iter = int(max_iter)
        self.adhesion = tm.MaugisAdhesionFunctional(self.surface)
        self.adhesion.parameters = {"rho": self.range, "surface_energy": float(work_of_adhesion)}
        self.solver.addFunctionalTerm(self.adhesion)

    def _run(self, mean_gap: float) -> tuple[int, float]:
        """Solve at the mean gap; ``(iterations, error)`` of the last line of tamaas' log."""
        log = _tamaas_log(self._tm, lambda: self.solver.solve(mean_gap))
        rows = [m.groups() for m in map(self._log_row.match, log.splitlines()) if m]
        if not rows:
            raise RuntimeError(f"could not read tamaas' iteration count from its log: {log!r}")
        return int(rows[-1][0]), float(rows[-1][2])

    def state(self) -> tuple[np.ndarray, np.ndarray]:
        """``(pressure, gap)`` of the last solve, ``(n, n)`` each."""
        pressure = np.array(self.model.traction, copy=True).reshape(self.n, self.n)
        gap = np.asarray(self.model.displacement).reshape(self.n, self.n) - self.surface
        return pressure, gap

    def law_residual(self, pressure: np.ndarray, gap: np.ndarray) -> float:
        """Largest violation of the Dugdale law over ``σ₀`` (:class:`AdhesionPeerPath`)."""
        open_ = gap > 0.0
        law = np.where(gap <= self.range, -self.sigma, 0.0)
        on_open = float(np.abs(pressure - law)[open_].max(initial=0.0))
        on_contact = float((-self.sigma - pressure)[~open_].max(initial=0.0))
        return max(on_open, on_contact) / self.sigma

    def path(self, depths, *, progress=None) -> AdhesionPeerPath:
        """Solve at each approach in order, warm-started; *progress(i, total)* after each."""
        depths = np.asarray(depths, dtype=float).reshape(-1)
        columns = {key: [] for key in ("force", "contact_cells", "zone_cells", "iterations", "error",
                                       "converged", "law_residual", "seconds")}
        for i, d in enumerate(depths):
            start = time.perf_counter()
            iterations, error = self._run(self.mean_height - float(d))
            seconds = time.perf_counter() - start
            pressure, gap = self.state()
            contact = gap <= 0.0
            for key, value in (("force", float(pressure.sum()) * (self.length / self.n) ** 2),
                               ("contact_cells", int(np.count_nonzero(contact))),
                               ("zone_cells", int(np.count_nonzero(~contact & (gap <= self.range)))),
                               ("iterations", iterations), ("error", error),
                               ("converged", error <= self.tol), ("law_residual", self.law_residual(pressure, gap)),
                               ("seconds", seconds)):
                columns[key].append(value)
            if progress is not None:
                progress(i + 1, depths.size)
        return AdhesionPeerPath(depth=depths, **{key: np.asarray(value) for key, value in columns.items()})


def make_peer(name: str, heights, *, length: float, e_star: float, tol: float = 1e-8):
    """Adapter for peer ``name`` (one of :data:`PEER_NAMES`) on ``heights``."""
    if name == "cm":
        return ContactMechanicsPeer(heights, length=length, e_star=e_star, tol=tol)
    if name == "tamaas":
        return TamaasPeer(heights, length=length, e_star=e_star, tol=tol)
    raise ValueError(f"unknown peer {name!r}; choose from {PEER_NAMES}")


def load_path(peer, forces, *, rel_step: float = 1e-3, progress=None) -> list[PeerPoint]:
    """Solve at each force in order (warm-started) with a difference-quotient stiffness.

    Parameters
    ----------
    peer : ContactMechanicsPeer or TamaasPeer
    forces : sequence of float
        Total forces, solved in the given order, each warm-started from the
        previous solution.
    rel_step : float
        Relative force step of the central difference quotient.
    progress : callable, optional
        Called as ``progress(i, len(forces), point)`` after each force.

    Returns
    -------
    list of PeerPoint
    """
    points = []
    previous = None
    forces = [float(f) for f in forces]
    for i, force in enumerate(forces):
        solution = peer.solve(force, initial=previous)
        start = time.perf_counter()
        upper = peer.solve(force * (1 + rel_step), initial=solution)
        lower = peer.solve(force * (1 - rel_step), initial=solution)
        stiffness_seconds = time.perf_counter() - start
        stiffness = (upper.force - lower.force) / (upper.depth - lower.depth)
        point = PeerPoint(force=force, depth=solution.depth, stiffness=stiffness,
                          iterations=solution.iterations,
                          stiffness_iterations=upper.iterations + lower.iterations,
                          solve_seconds=solution.seconds, stiffness_seconds=stiffness_seconds,
                          contact_cells=int(np.count_nonzero(solution.contact)))
        points.append(point)
        previous = solution
        if progress is not None:
            progress(i + 1, len(forces), point)
    return points


def peer_versions() -> dict[str, str]:
    """Installed versions of the peer packages (``"not installed"`` if absent)."""
    versions = {}
    for package in ("ContactMechanics", "SurfaceTopography", "NuMPI", "tamaas"):
        try:
            versions[package] = version(package)
        except PackageNotFoundError:
            versions[package] = "not installed"
    return versions
