"""The tool's solid on the rays of a bar on a rotary axis (``rotary.py``): the radii each part covers.

The bar's frame: ``axial`` along its axis, ``p`` and ``q`` across it with q up (the tool points
down -q); a ray from the axis at machine angle φ (from +p towards +q) is ρ (cos φ, sin φ).  A tool
pose is (axial, p, q of its tip, the angle the bar is turned by, degrees).  Each part of the tool
(the cutter, the shank and the holder above it) is a solid of revolution about the tool's vertical
axis, ``bottom`` to ``top`` above the tip: in the slice at ``dx`` from the tool's axis it is the
set ``|u| <= half`` (u = p - tip p, half = sqrt(r² - dx²)) with ``bottom + g(u) <= q - tip q <=
top``, g the cutter's profile at the distance sqrt(dx² + u²) from its axis (0 for a flat end, the
shank and the holder).  That set is convex, so a ray meets it in one interval of radii: for a flat
bottom the interval is closed-form (a strip and two half-planes), for a ball too (a disc joined to
the strip above its centre) and a vee (the cone's upper nappe: a quadratic); for a bull cutter
ρ s - tip q - g(ρ c - tip p) is concave along the ray, so its top is found by a golden-section
search and the interval's two ends by bisection on either side (exact to ``TOLERANCE``).
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.tools import Tool

CUT, RAPID, SPINDLE_OFF, SHANK, HOLDER = range(5)  # what removing material with a part means
GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0
STEPS = 32  # golden-section and bisection steps: 0.618^32 (2e-7) and 2^-32 of the ray's span


@dataclass(frozen=True)
class Part:
    """A piece of the tool: ``radius``, from ``bottom`` to ``top`` above the tip; ``cutter`` gives the
    profile of a shaped cutter's bottom (None: flat); ``code`` CUT (the move's own code), SHANK or HOLDER."""

    radius: float
    bottom: float
    top: float
    code: int
    cutter: Tool | None = None


def parts_of(tool: Tool) -> list[Part]:
    """The parts from the outside in (holder, shank, cutter): in one pose the outer part meets the
    material first.  Without ``flute_length`` the cutter reaches up for ever (nothing else is checked)."""
    shaped = tool if tool.shape not in ("flat", "insert") else None
    if tool.flute_length is None:
        return [Part(tool.radius, 0.0, math.inf, CUT, shaped)]
    held = tool.holder_length is not None and tool.holder_diameter is not None
    shank_top = float(tool.holder_length) if held and tool.holder_length is not None else math.inf
    parts = [Part(tool.shank_radius, tool.flute_length, shank_top, SHANK), Part(tool.radius, 0.0, tool.flute_length,
                                                                                 CUT, shaped)]
    if held and tool.holder_diameter is not None:
        parts.insert(0, Part(tool.holder_diameter / 2.0, shank_top, math.inf, HOLDER))
    return parts


def stamps(stock: RoundStock, poses: np.ndarray, radius: float, part: Part | None = None
           ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(sample, cell, low, high): for each pose the interval of radii ``part`` (default: a flat end
    mill of ``radius`` from the tip upwards) covers on each cell's ray, pose by pose, slice by slice,
    angle by angle.  A ray's angle and its heights depend on the pose and the angle only, the tool's
    width on the pose and the slice only: each is worked out once (the trigonometry per pose and
    angle, not per cell), the rays a pose cannot reach (a slice beyond the tool's radius, an angle
    whose heights leave no interval) are dropped before the pairs are formed."""
    part = part or Part(radius, 0.0, math.inf, CUT)
    first, slices, first_angle, spread, _ = extent(stock, poses, part)
    step = math.radians(stock.angle_step())
    angles = stock.shape[1]
    capped = math.isfinite(part.top) and float(poses[:, 2].min()) + part.top < float(stock.outer.max())
    # (pose, angle) rays: their direction and the interval the part's heights leave on them
    pose_a = np.repeat(np.arange(len(poses)), spread)
    angle = (first_angle[pose_a] + (np.arange(len(pose_a)) - np.repeat(np.cumsum(spread) - spread, spread))) % angles
    z_a = poses[pose_a, 2]
    phi = (angle + 0.5) * step + np.radians(poses[pose_a, 3])
    c, s = np.cos(phi), np.sin(phi)
    lo_a, hi_a = _heights(z_a + part.bottom, z_a + part.top if capped else None, s)
    ray = np.flatnonzero((lo_a < hi_a) & (hi_a >= 0))
    pose_a, angle, c, s, lo_a, hi_a = pose_a[ray], angle[ray], c[ray], s[ray], lo_a[ray], hi_a[ray]
    per_a = np.bincount(pose_a, minlength=len(poses))
    # (pose, slice) rows within the tool's radius: the half width of its slice there
    rows = np.where(per_a > 0, slices, 0)
    pose_s = np.repeat(np.arange(len(poses)), rows)
    slice_ = first[pose_s] + (np.arange(len(pose_s)) - np.repeat(np.cumsum(rows) - rows, rows))
    dx = stock.centres()[slice_] - poses[pose_s, 0]
    row = np.flatnonzero(np.abs(dx) <= part.radius)
    pose_s, slice_, dx = pose_s[row], slice_[row], dx[row]
    half = np.sqrt(np.maximum(part.radius * part.radius - dx * dx, 0.0))
    # the pairs: each row with each ray of its pose, in that order
    width = per_a[pose_s]
    ray_start = np.cumsum(per_a) - per_a
    pair_s = np.repeat(np.arange(len(pose_s)), width)
    pair_a = np.arange(len(pair_s)) - np.repeat(np.cumsum(width) - width - ray_start[pose_s], width)
    y = poses[pose_s, 1]
    low, high = _sides(y, half, c, pair_s, pair_a)
    np.maximum(lo_a[pair_a], low, out=low)  # (in _flat's order: the same zero's sign on a tie)
    np.minimum(hi_a[pair_a], high, out=high)
    keep = low < high
    keep &= high >= 0
    if part.cutter is not None and keep.any():
        k = np.flatnonzero(keep)
        ks, ka = pair_s[k], pair_a[k]
        kp = pose_s[ks]
        dx_k, y_k, z_k, c_k, s_k = dx[ks], y[ks], poses[kp, 2], c[ka], s[ka]
        if part.cutter.shape == "ball":
            low[k], high[k] = _ball(part, dx_k, y_k, z_k, half[ks], c_k, s_k)
        elif part.cutter.shape == "vee":
            lo, hi = _vee(part.cutter.cone_slope, dx_k, y_k, z_k, c_k, s_k)
            low[k], high[k] = np.maximum(lo, low[k]), np.minimum(hi, high[k])
        else:
            top = float(stock.outer.max()) + 1.0  # beyond the surface every interval only needs to reach it
            lo, hi = _shaped(part.cutter, dx_k, y_k, z_k, c_k, s_k, np.maximum(low[k], -1.0), np.minimum(high[k], top))
            low[k] = lo
            high[k] = np.where(hi >= top, high[k], hi)  # reaching past the surface: as the flat part's
        keep &= (high >= 0) & (low <= high)
    k = np.flatnonzero(keep)
    ks = pair_s[k]
    return pose_s[ks], slice_[ks] * angles + angle[pair_a[k]], low[k], high[k]


def _flat(y: np.ndarray, bottom: np.ndarray, top: np.ndarray | None, half: np.ndarray, c: np.ndarray,
          s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The ray's interval in the strip |ρ c - y| <= half between the heights ``bottom`` and ``top``
    (None: no top, as for a part reaching up past the bar)."""
    lo, hi = _heights(bottom, top, s)
    side_lo, side_hi = _sides(y, half, c)
    return np.maximum(lo, side_lo), np.minimum(hi, side_hi)


def _heights(bottom: np.ndarray, top: np.ndarray | None, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The ray's interval between the heights ``bottom`` and ``top`` (None: none), ``s`` its sine."""
    with np.errstate(divide="ignore", invalid="ignore"):
        up, down = s > 1e-12, s < -1e-12
        level = ~up & ~down  # a ray along p: all of it between the heights when 0 is, else none
        between = (bottom <= 0) if top is None else (bottom <= 0) & (top >= 0)
        along = np.where(level & between, -np.inf, np.inf)
        if top is None:
            lo = np.where(up, bottom / s, np.where(down, -np.inf, along))
            hi = np.where(up, np.inf, np.where(down, bottom / s, -along))
        else:
            lo = np.where(up, bottom / s, np.where(down, top / s, along))
            hi = np.where(up, top / s, np.where(down, bottom / s, -along))
    return lo, hi


def _sides(y: np.ndarray, half: np.ndarray, c: np.ndarray, row: np.ndarray | None = None,
           ray: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The ray's interval in the strip |ρ c - y| <= half, ``c`` its cosine (a ray along q: inside the
    tool's width or not at all); with ``row`` and ``ray``, of the pairs (``y[row]``, ``half[row]``,
    ``c[ray]``): the strip's edges y ± half worked out once a row."""
    row = np.arange(len(y)) if row is None else row
    ray = np.arange(len(c)) if ray is None else ray
    with np.errstate(divide="ignore", invalid="ignore"):
        right, level = c > 1e-12, np.abs(c) <= 1e-12  # (not right and not level: left, c < -1e-12)
        edge = (y - half)[row] / c[ray]  # the edge a ray to the right (c > 0) enters at, one to the left leaves at
        other = (y + half)[row] / c[ray]
        facing = right[ray]
        side_lo, side_hi = np.where(facing, edge, other), np.where(facing, other, edge)
        if level.any():
            along = np.flatnonzero(level[ray])
            across = np.abs(y[row[along]]) <= half[row[along]]
            side_lo[along] = np.where(across, -np.inf, np.inf)
            side_hi[along] = np.where(across, np.inf, -np.inf)
    return side_lo, side_hi


def _ball(part: Part, dx: np.ndarray, y: np.ndarray, z: np.ndarray, half: np.ndarray, c: np.ndarray,
          s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A ball cutter's slice: the disc of radius ``half`` about its centre (y, z + r), below the cap
    at ``top``, joined with the strip above the centre; the ray's interval in that convex union."""
    centre = z + part.radius
    b = c * y + s * centre
    root = np.sqrt(np.maximum(b * b - (y * y + centre * centre - half * half), 0.0))
    hit = b * b >= y * y + centre * centre - half * half
    infinite = np.full_like(y, np.inf)
    cap_lo, cap_hi = _flat(y, -infinite, z + part.top if math.isfinite(part.top) else None, infinite, c, s)
    disc_lo, disc_hi = np.maximum(b - root, cap_lo), np.minimum(b + root, cap_hi)
    hit &= disc_lo <= disc_hi  # the cap may take the disc's part of the ray away
    disc_lo, disc_hi = np.where(hit, disc_lo, np.inf), np.where(hit, disc_hi, -np.inf)
    strip_lo, strip_hi = _flat(y, centre, z + part.top if math.isfinite(part.top) else None, half, c, s)
    missed = strip_lo > strip_hi  # an empty piece must not widen the union
    strip_lo, strip_hi = np.where(missed, np.inf, strip_lo), np.where(missed, -np.inf, strip_hi)
    return np.minimum(disc_lo, strip_lo), np.maximum(disc_hi, strip_hi)


def _vee(slope: float, dx: np.ndarray, y: np.ndarray, z: np.ndarray, c: np.ndarray, s: np.ndarray
         ) -> tuple[np.ndarray, np.ndarray]:
    """A vee cutter's cone, q - z >= slope sqrt(dx² + u²) (its upper nappe), on the ray: where the
    quadratic (ρ s - z)² - slope² (dx² + (ρ c - y)²) is >= 0 on that nappe.  A ray steeper than the
    cone crosses each nappe once and stays inside the upper one beyond its root; a shallower one is
    inside between its two roots, if they lie on the upper nappe."""
    k2 = slope * slope
    a = s * s - k2 * c * c
    a = np.where(np.abs(a) < 1e-12, 1e-12, a)  # a ray along the cone's side: as a hair steeper
    b = -2.0 * (s * z - k2 * c * y)
    c0 = z * z - k2 * (dx * dx + y * y)
    disc = b * b - 4.0 * a * c0
    root = np.sqrt(np.maximum(disc, 0.0))
    half = -(b + np.where(b >= 0.0, root, -root)) / 2.0  # the stable form: no cancellation
    with np.errstate(divide="ignore", invalid="ignore"):
        r1, r2 = half / a, np.where(half != 0.0, c0 / half, 0.0)
    near, far = np.minimum(r1, r2), np.maximum(r1, r2)
    steep = a > 0.0
    lo = np.where(steep, np.where(s > 0.0, far, -np.inf), near)
    hi = np.where(steep, np.where(s > 0.0, np.inf, near), far)
    upper = ((near + far) / 2.0) * s - z >= 0.0
    missed = (disc < 0.0) | (~steep & ~upper)
    return np.where(missed, np.inf, lo), np.where(missed, -np.inf, hi)


def _shaped(tool: Tool, dx: np.ndarray, y: np.ndarray, z: np.ndarray, c: np.ndarray, s: np.ndarray,
            a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Within the flat cutter's interval [a, b] of each ray, where ρ s - z - g(ρ c - y) >= 0 (g the
    cutter's profile): the top of that concave function, then its zeros either side (lo > hi: none)."""
    def f(rho: np.ndarray) -> np.ndarray:
        u = rho * c - y
        return rho * s - z - tool.profile(np.sqrt(dx * dx + u * u))

    lo, hi = a.copy(), b.copy()
    left, right = hi - GOLDEN * (hi - lo), lo + GOLDEN * (hi - lo)
    f_left, f_right = f(left), f(right)
    for _ in range(STEPS):
        rising = f_left < f_right  # the top lies right of ``left``
        lo = np.where(rising, left, lo)
        hi = np.where(rising, hi, right)
        left, right = np.where(rising, right, hi - GOLDEN * (hi - lo)), np.where(rising, lo + GOLDEN * (hi - lo), left)
        f_new = f(np.where(rising, right, left))
        f_left, f_right = np.where(rising, f_right, f_new), np.where(rising, f_new, f_left)
    peak = (lo + hi) / 2.0
    inside = f(peak) >= 0.0
    return _zero(f, a, peak, rising=True, inside=inside), _zero(f, peak, b, rising=False, inside=inside)


def _zero(f: Callable[[np.ndarray], np.ndarray], a: np.ndarray, b: np.ndarray, rising: bool, inside: np.ndarray) -> np.ndarray:
    """Where the concave ``f`` crosses 0 between ``a`` and ``b`` (up when ``rising``); the end itself
    when it is already inside; NaN-free: a ray missing the cutter gets lo > hi from its caller."""
    end = a if rising else b
    at_end = f(end) >= 0.0
    lo, hi = a.copy(), b.copy()
    for _ in range(STEPS):
        mid = (lo + hi) / 2.0
        above = f(mid) >= 0.0
        if rising:
            hi = np.where(above, mid, hi)
            lo = np.where(above, lo, mid)
        else:
            lo = np.where(above, mid, lo)
            hi = np.where(above, hi, mid)
    found = np.where(at_end, end, hi if rising else lo)
    return np.where(inside, found, np.inf if rising else -np.inf)


def extent(stock: RoundStock, poses: np.ndarray, part: Part) -> tuple[np.ndarray, ...]:
    """Per pose: the first slice and how many, the first angle cell and how many (the machine angles
    the part can reach: sin(phi) >= q / top for its bottom above the axis, all for one below it),
    and their product, the cells to look at."""
    radius = part.radius
    top = float(stock.outer.max())
    z = poses[:, 2] + part.bottom
    reach = z < top  # a part above the bar touches nothing
    first = np.clip(np.ceil((poses[:, 0] - radius - stock.start) / stock.resolution - 0.5), 0, stock.shape[0])
    last = np.clip(np.floor((poses[:, 0] + radius - stock.start) / stock.resolution - 0.5), -1, stock.shape[0] - 1)
    slices = np.where(reach, last - first + 1, 0).astype(np.int64).clip(0)
    y = poses[:, 1]
    rise = np.where(z > 0, np.arcsin(np.clip(z / max(top, 1e-9), -1, 1)), -math.pi / 2)
    # above the axis the part's bottom corners bound the angles too (the rays reach it between them)
    low = np.where(z > 0, np.maximum(rise, np.arctan2(z, y + radius)), rise)
    high = np.where(z > 0, np.minimum(math.pi - rise, np.arctan2(z, y - radius)), math.pi - rise)
    step = math.radians(stock.angle_step())
    spread = np.where((slices > 0) & (high >= low), np.ceil((high - low) / step).astype(np.int64) + 3, 0)
    spread = np.minimum(spread, stock.shape[1])
    first_angle = np.floor((low - np.radians(poses[:, 3])) / step - 0.5).astype(np.int64) - 1
    return first.astype(np.int64), slices, first_angle, spread, slices * spread
