"""Independent float64 reference for the in-scattered radiance L_in (numpy only).

Computes, for every pixel-centre view ray of a camera (perspective or parallel), the integral of
the model that vtkLightShaftPass documents, summed over the lights:

    L_in = sum over lights of
           int_0^{t_s} sigma_s p(cos theta) I S(x) A(r) V(x) exp(-sigma_t r) exp(-sigma_t t) dt

(with an analytic density rho (Medium.density): sigma_s rho(x) in front, and sigma_t times the
integrals of rho along both legs in the exponent)

for an analytic scene made of spheres and finite horizontal floors (both stop view rays and cast
shadows), lit by spotlights, point lights and directional lights. Nothing here uses the pass or
VTK's matrices: rays come from the camera's position, focal point, view-up,
view angle (or parallel scale) and clipping range; surfaces and shadows are exact (ray-sphere
and ray-plane hits; a sphere's shadow from a spot or point light is the part of its tangent cone
beyond the tangent circle, from a directional light the half-cylinder beyond its centre; a
floor's shadow is where the segment to the light crosses its rectangle, one interval). The
ray is split at every breakpoint (where the light starts or stops shining, shadow entry/exit,
surface) and each smooth piece is integrated by composite Gauss-Legendre quadrature: about a
spot or point light in s with x = h sinh(s) (x along the ray from its point closest to the
light, h the distance between them: the phase function and A(r) dx/ds are smooth in s however
close the ray passes), in t for a directional light.

Conventions shared with the pass (P the light's position, a the unit direction to its focal
point): cos theta = -d . l with l the direction the light travels at x, so theta = 0 is forward
scattering; A = 1 / (c0 + c1 r + c2 r^2) (all zero taken as 1); image row 0 at the bottom.
- Spotlight: r = |x - P|, l = (x - P) / r, S = cos(angle to a)^exponent inside the cone
  half-angle and 0 outside.
- PointLight: as a spot without the cone (S = 1); no cookie.
- DirectionalLight: r = (x - P) . a, the distance from the plane through P perpendicular to a;
  lit where r >= 0; l = a; S = A = 1; its cookie tiles the plane with period |focal - P|.
"""

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np

ISOTROPIC, HENYEY_GREENSTEIN, RAYLEIGH = 0, 1, 2


@dataclass
class Camera:
    position: tuple
    focal_point: tuple
    view_up: tuple
    view_angle: float  # vertical, degrees (VTK's default)
    clipping_range: tuple  # (near, far): rays that hit nothing end at view depth far
    width: int
    height: int
    # Parallel projection: rays start on the plane through the position across the view (half
    # its height is parallel_scale, as VTK's) and all run along the view direction.
    parallel: bool = False
    parallel_scale: float = 1.0


@dataclass
class Spotlight:
    position: tuple
    focal_point: tuple
    cone_angle: float  # half-angle, degrees
    exponent: float = 1.0
    attenuation: tuple = (1.0, 0.0, 0.0)
    intensity: float = 1.0
    color: tuple = (1.0, 1.0, 1.0)
    # Optional cookie: cookie(u, v) -> (n, 3) RGB factors, u, v in [0, 1] across the square
    # that circumscribes the cone, laid out as vtkLightShaftPass lays it (see light_basis).
    cookie: object = None
    kind: ClassVar[str] = "spot"


@dataclass
class PointLight:
    """A positional light without a cone (VTK: cone angle of 90 degrees or more); no cookie."""
    position: tuple
    attenuation: tuple = (1.0, 0.0, 0.0)
    intensity: float = 1.0
    color: tuple = (1.0, 1.0, 1.0)
    kind: ClassVar[str] = "point"


@dataclass
class DirectionalLight:
    """Parallel light travelling from position towards focal_point, lighting the half-space
    beyond the plane through position perpendicular to that direction (VTK: not positional;
    no attenuation)."""
    position: tuple
    focal_point: tuple
    intensity: float = 1.0
    color: tuple = (1.0, 1.0, 1.0)
    # Optional cookie: cookie(u, v) -> (n, 3) RGB factors of u, v wrapped into [0, 1): the
    # square of side |focal_point - position| centred on the axis through position, laid out
    # as the spot's (see light_basis), repeating over the plane.
    cookie: object = None
    kind: ClassVar[str] = "directional"


@dataclass
class Medium:
    scattering: tuple
    absorption: tuple = (0.0, 0.0, 0.0)
    phase: int = ISOTROPIC
    anisotropy: float = 0.0
    # Optional analytic density (vtkLightShaftPass::SetMediumDensity's rho, scaled and with its
    # background): density(x) -> (n,) for points (n, 3) scales sigma_s and sigma_t at x, and
    # optical_depth(a, b) -> (n,) is its exact integral along the segments a -> b.
    density: object = None
    optical_depth: object = None


@dataclass
class Scene:
    spheres: list = field(default_factory=list)  # (centre, radius)
    floors: list = field(default_factory=list)  # (height y, xmin, xmax, zmin, zmax)


def _normalize(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _dot(a, b):
    """Row-wise dot product (broadcasting one point against many)."""
    return np.sum(a * b, axis=-1)


def camera_rays(cam):
    """The pixel-centre rays, row 0 at the bottom: origins (the eye (3,), or (h, w, 3) for a
    parallel camera), unit directions (h, w, 3), and the view direction."""
    eye = np.asarray(cam.position, float)
    forward = _normalize(np.asarray(cam.focal_point, float) - eye)
    right = _normalize(np.cross(forward, np.asarray(cam.view_up, float)))
    up = np.cross(right, forward)
    half = cam.parallel_scale if cam.parallel else np.tan(np.radians(cam.view_angle) / 2.0)
    aspect = cam.width / cam.height
    x = (2.0 * (np.arange(cam.width) + 0.5) / cam.width - 1.0) * half * aspect
    y = (2.0 * (np.arange(cam.height) + 0.5) / cam.height - 1.0) * half
    offsets = x[None, :, None] * right + y[:, None, None] * up
    if cam.parallel:
        return eye + offsets, np.broadcast_to(forward, offsets.shape).copy(), forward
    return eye, _normalize(offsets + forward), forward


def surface_distance(eye, dirs, forward, cam, scene):
    """Distance to the first surface along each ray (origins `eye`: one point or one per ray),
    or to the far depth (the pass's backdrop, render_helpers.backdrop_depth)."""
    t = cam.clipping_range[1] / (dirs @ forward)
    for centre, radius in scene.spheres:
        m = eye - np.asarray(centre, float)
        b = _dot(dirs, m)
        c = _dot(m, m) - radius * radius
        disc = b * b - c
        hit = disc >= 0.0
        t_hit = -b - np.sqrt(np.where(hit, disc, 0.0))
        ok = hit & (t_hit > 0.0) & (t_hit < t)
        t = np.where(ok, t_hit, t)
    for height, xmin, xmax, zmin, zmax in scene.floors:
        dy = dirs[..., 1]
        with np.errstate(divide="ignore", invalid="ignore"):
            t_hit = (height - eye[..., 1]) / dy
        p = eye + t_hit[..., None] * dirs
        ok = (t_hit > 0.0) & (t_hit < t) & (p[..., 0] >= xmin) & (p[..., 0] <= xmax) \
            & (p[..., 2] >= zmin) & (p[..., 2] <= zmax)
        t = np.where(ok, t_hit, t)
    return t


def cone_interval(origin, dirs, apex, axis, cos_half):
    """Parameter interval [t0, t1] of origin + t d inside a cone's forward nappe (t0 > t1: empty)."""
    m = origin - apex
    da = dirs @ axis
    ma = m @ axis
    dm = _dot(dirs, m)
    c2 = cos_half * cos_half
    qa = da * da - c2
    qb = 2.0 * (da * ma - c2 * dm)
    qc = ma * ma - c2 * _dot(m, m)
    inf = np.inf
    lo = np.full(da.shape, -inf)
    hi = np.full(da.shape, inf)
    # forward half-space (m + t d) . axis >= 0
    with np.errstate(divide="ignore", invalid="ignore"):
        t_plane = -ma / da
    lo = np.where(da > 0, t_plane, lo)
    hi = np.where(da < 0, t_plane, hi)
    empty = (da == 0) & (ma < 0)
    disc = qb * qb - 4.0 * qa * qc
    sq = np.sqrt(np.maximum(disc, 0.0))
    q = -0.5 * (qb + np.where(qb >= 0, 1.0, -1.0) * sq)
    with np.errstate(divide="ignore", invalid="ignore"):
        r1 = q / qa
        r2 = np.where(q != 0, qc / q, r1)
    t_in = np.minimum(r1, r2)
    t_out = np.maximum(r1, r2)
    inside_between = qa < 0  # quadric >= 0 between the roots
    empty |= (disc < 0) & inside_between
    real = disc >= 0
    lo_between = np.maximum(lo, t_in)
    hi_between = np.minimum(hi, t_out)
    # qa > 0: outside the roots; the half-space picks the nappe.
    before = lo <= t_in
    after = hi >= t_out
    lo_out = np.where(after & ~before, np.maximum(lo, t_out), lo)
    hi_out = np.where(before & ~after, np.minimum(hi, t_in), hi)
    empty |= real & ~inside_between & ~before & ~after
    lo = np.where(real & inside_between, lo_between, np.where(real, lo_out, lo))
    hi = np.where(real & inside_between, hi_between, np.where(real, hi_out, hi))
    lo = np.where(empty, inf, lo)
    hi = np.where(empty, -inf, hi)
    return lo, hi


def sphere_shadow_interval(origin, dirs, light, centre, radius):
    """Where the ray is in the sphere's shadow: tangent cone beyond the tangent circle."""
    light = np.asarray(light, float)
    centre = np.asarray(centre, float)
    to_centre = centre - light
    dist = np.linalg.norm(to_centre)
    if dist <= radius:
        return np.full(dirs.shape[:-1], -np.inf), np.full(dirs.shape[:-1], np.inf)
    axis = to_centre / dist
    cos_half = np.sqrt(dist * dist - radius * radius) / dist
    lo, hi = cone_interval(origin, dirs, light, axis, cos_half)
    plane = (dist * dist - radius * radius) / dist  # axial distance of the tangent circle
    da = dirs @ axis
    ma = (origin - light) @ axis
    with np.errstate(divide="ignore", invalid="ignore"):
        t_plane = (plane - ma) / da
    lo = np.where(da > 0, np.maximum(lo, t_plane), lo)
    hi = np.where(da < 0, np.minimum(hi, t_plane), hi)
    never = (da == 0) & (ma < plane)
    return np.where(never, np.inf, lo), np.where(never, -np.inf, hi)


def cylinder_shadow_interval(origin, dirs, axis, centre, radius):
    """Where the ray is in a sphere's shadow under parallel light travelling along `axis`:
    within `radius` of the line through the centre along the axis, beyond the centre."""
    axis = np.asarray(axis, float)
    m = origin - np.asarray(centre, float)
    ma = np.asarray(m @ axis)
    da = dirs @ axis
    m_perp = m - np.multiply.outer(ma, axis)
    d_perp = dirs - da[..., None] * axis
    qa = _dot(d_perp, d_perp)
    qb = 2.0 * _dot(m_perp, d_perp)
    qc = _dot(m_perp, m_perp) - radius * radius
    disc = qb * qb - 4.0 * qa * qc
    sq = np.sqrt(np.maximum(disc, 0.0))
    q = -0.5 * (qb + np.where(qb >= 0, 1.0, -1.0) * sq)
    with np.errstate(divide="ignore", invalid="ignore"):
        r1 = q / qa
        r2 = np.where(q != 0, qc / q, r1)
        t_plane = -ma / da
    lo = np.minimum(r1, r2)
    hi = np.maximum(r1, r2)
    parallel = qa <= 1e-300  # along the axis: inside for every t, or for none
    lo = np.where(parallel, np.where(qc <= 0, -np.inf, np.inf), lo)
    hi = np.where(parallel, np.where(qc <= 0, np.inf, -np.inf), hi)
    lo = np.where(~parallel & (disc < 0), np.inf, lo)
    hi = np.where(~parallel & (disc < 0), -np.inf, hi)
    # Beyond the centre: (m + t d) . axis > 0.
    lo = np.where(da > 0, np.maximum(lo, t_plane), lo)
    hi = np.where(da < 0, np.minimum(hi, t_plane), hi)
    never = (da == 0) & (ma <= 0)
    return np.where(never, np.inf, lo), np.where(never, -np.inf, hi)


def _half_line(lo, hi, alpha, beta):
    """[lo, hi] narrowed to where alpha + beta t >= 0."""
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -alpha / beta
    lo = np.where(beta > 0, np.maximum(lo, t), lo)
    hi = np.where(beta < 0, np.minimum(hi, t), hi)
    never = (beta == 0) & (alpha < 0)
    return np.where(never, np.inf, lo), np.where(never, -np.inf, hi)


def floor_shadow_interval(light, origin, dirs, floor):
    """Where the ray is in a floor rectangle's shadow: the segment from x to a spot or point
    light, or from x back along a to a directional light's plane, crosses the rectangle. Every
    condition is linear in t (for a positional light after multiplying by the distance across
    the floor's plane, positive on the far side), so the shadow is one interval."""
    height, xmin, xmax, zmin, zmax = floor
    shape = dirs.shape[:-1]
    o = np.broadcast_to(origin, dirs.shape)
    lo, hi = np.full(shape, -np.inf), np.full(shape, np.inf)
    position = np.asarray(light.position, float)
    if light.kind == "directional":
        a = _axis(light)
        if a[1] == 0.0:
            return np.full(shape, np.inf), np.full(shape, -np.inf)
        # The segment meets the floor's plane at p = x - s a, s = (y - height) / a_y >= 0,
        # which must lie beyond the light's plane: r(p) = r(x) - s >= 0.
        s0, s1 = (o[..., 1] - height) / a[1], dirs[..., 1] / a[1]
        lo, hi = _half_line(lo, hi, s0, s1)
        lo, hi = _half_line(lo, hi, (o - position) @ a - s0, dirs @ a - s1)
        for c, (cmin, cmax) in ((0, (xmin, xmax)), (2, (zmin, zmax))):
            alpha, beta = o[..., c] - a[c] * s0, dirs[..., c] - a[c] * s1
            lo, hi = _half_line(lo, hi, alpha - cmin, beta)
            lo, hi = _half_line(lo, hi, cmax - alpha, -beta)
        return lo, hi
    q = position[1] - height  # the light's height above the floor's plane
    if q == 0.0:
        return np.full(shape, np.inf), np.full(shape, -np.inf)
    sg = np.sign(q)
    # x on the far side of the plane; there D = sg (L_y - y) > 0 and p_c = L_c + (x_c - L_c) q /
    # (L_y - y), so cmin <= p_c <= cmax is linear in t once multiplied by D.
    lo, hi = _half_line(lo, hi, sg * (height - o[..., 1]), -sg * dirs[..., 1])
    across0, across1 = position[1] - o[..., 1], -dirs[..., 1]
    for c, (cmin, cmax) in ((0, (xmin, xmax)), (2, (zmin, zmax))):
        along0, along1 = (o[..., c] - position[c]) * q, dirs[..., c] * q
        lo, hi = _half_line(lo, hi, sg * ((position[c] - cmin) * across0 + along0),
                            sg * ((position[c] - cmin) * across1 + along1))
        lo, hi = _half_line(lo, hi, sg * ((cmax - position[c]) * across0 - along0),
                            sg * ((cmax - position[c]) * across1 - along1))
    return lo, hi


def _axis(light):
    """Unit direction from the light's position to its focal point."""
    return _normalize(np.asarray(light.focal_point, float) - np.asarray(light.position, float))


def _attenuation(light):
    """(c0, c1, c2); all zero (VTK would divide by zero) is taken as no falloff."""
    c0, c1, c2 = (float(c) for c in light.attenuation)
    if c0 <= 0.0 and c1 <= 0.0 and c2 <= 0.0:
        c0 = 1.0
    return c0, c1, c2


def light_basis(light):
    """(forward, right, up) of the light's camera as vtkLightShaftPass builds it: view-up is
    world +Y, or +X for a light aiming within ~8 degrees of the Y axis."""
    forward = _axis(light)
    up0 = np.array([0.0, 1.0, 0.0]) if abs(forward[1]) < 0.99 else np.array([1.0, 0.0, 0.0])
    right = _normalize(np.cross(forward, up0))
    return forward, right, np.cross(right, forward)


def cookie_uv(light, points):
    """Cookie coordinates (u, v) of world points, for the pass's light camera: across a
    spotlight's square in perspective; for a directional light across the square of side
    |focal - position| centred on its axis, unwrapped (the cookie repeats with period 1)."""
    forward, right, up = light_basis(light)
    d = points - np.asarray(light.position, float)
    if light.kind == "directional":
        side = np.linalg.norm(np.asarray(light.focal_point, float) -
                              np.asarray(light.position, float))
        return (d @ right) / side + 0.5, (d @ up) / side + 0.5
    depth = d @ forward
    tan_half = np.tan(np.radians(min(light.cone_angle, 89.9)))
    with np.errstate(divide="ignore", invalid="ignore"):
        u = 0.5 * (d @ right) / (depth * tan_half) + 0.5
        v = 0.5 * (d @ up) / (depth * tan_half) + 0.5
    return u, v


def lit_interval(light, origin, dirs):
    """Parameter interval [t0, t1] of origin + t d where the light shines (t0 > t1: none): the
    spot's cone (forward nappe), everywhere for a point light, the half-space beyond a
    directional light's plane."""
    shape = dirs.shape[:-1]
    if light.kind == "point":
        return np.full(shape, -np.inf), np.full(shape, np.inf)
    lpos = np.asarray(light.position, float)
    axis = _axis(light)
    if light.kind == "spot":
        return cone_interval(origin, dirs, lpos, axis, np.cos(np.radians(light.cone_angle)))
    k = dirs @ axis
    r0 = np.broadcast_to((origin - lpos) @ axis, shape)
    with np.errstate(divide="ignore", invalid="ignore"):
        t_plane = -r0 / k
    lo = np.where(k > 0, t_plane, -np.inf)
    hi = np.where(k < 0, t_plane, np.inf)
    empty = (k == 0) & (r0 < 0)
    return np.where(empty, np.inf, lo), np.where(empty, -np.inf, hi)


def shadow_interval(light, origin, dirs, centre, radius):
    """Where the ray is in a sphere's shadow for `light`."""
    if light.kind == "directional":
        lpos = np.asarray(light.position, float)
        axis = _axis(light)
        assert (np.asarray(centre, float) - lpos) @ axis >= radius, \
            "a sphere must lie entirely beyond the directional light's plane"
        return cylinder_shadow_interval(origin, dirs, axis, centre, radius)
    return sphere_shadow_interval(origin, dirs, light.position, centre, radius)


def _phase(cos_theta, medium):
    if medium.phase == HENYEY_GREENSTEIN:
        g = medium.anisotropy
        denom = 1.0 + g * g - 2.0 * g * cos_theta
        return (1.0 - g * g) / (4.0 * np.pi * denom ** 1.5)
    if medium.phase == RAYLEIGH:
        return 3.0 / (16.0 * np.pi) * (1.0 + cos_theta ** 2)
    return np.full_like(cos_theta, 1.0 / (4.0 * np.pi))


_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(16)


def _variable(light, eye, dirs):
    """The integration variable of each ray for `light`: (to_var(t), from_var(u) -> (t, dt/du)).
    About a spot or point light, with b and h the ray's foot and distance from the light:
    u = asinh((t + b) / h), in which r = h cosh u, cos theta = -tanh u and A(r) dt/du are
    smooth for any attenuation and phase however close the ray passes (1 / (c2 h cosh u) for
    A = 1 / (c2 r^2)); t for a directional light."""
    if light.kind == "directional":
        return (lambda t: t), (lambda u: (u, 1.0))
    m = eye - np.asarray(light.position, float)
    b = _dot(dirs, m)
    h = np.sqrt(np.maximum(_dot(m, m) - b * b, 0.0))
    h = np.maximum(h, 1e-12 * np.maximum(np.abs(b), 1.0))
    return (lambda t: np.arcsinh((t + b) / h)), \
        (lambda u: (h * np.sinh(u) - b, h * np.cosh(u)))


def _integrate_pieces(eye, dirs, t0, t1, light, medium, panels):
    """Composite Gauss-Legendre of the (visible) integrand over [t0, t1] per ray; returns (n, 3)."""
    lpos = np.asarray(light.position, float)
    directional = light.kind == "directional"
    axis = None if light.kind == "point" else _axis(light)
    c0, c1, c2 = (1.0, 0.0, 0.0) if directional else _attenuation(light)
    intensity = light.intensity * np.asarray(light.color, float)
    sigma_s = np.asarray(medium.scattering, float)
    sigma_t = sigma_s + np.asarray(medium.absorption, float)
    cookie = getattr(light, "cookie", None)
    valid = t1 > t0
    t0 = np.where(valid, t0, 0.0)
    t1 = np.where(valid, t1, 0.0)
    to_var, from_var = _variable(light, eye, dirs)
    u0 = to_var(t0)
    u1 = to_var(t1)
    total = np.zeros(dirs.shape[:-1] + (3,))
    edges = np.linspace(0.0, 1.0, panels + 1)
    for k in range(panels):
        a = u0 + (u1 - u0) * edges[k]
        c = u0 + (u1 - u0) * edges[k + 1]
        half = 0.5 * (c - a)
        mid = 0.5 * (c + a)
        for node, weight in zip(_NODES, _WEIGHTS):
            t, jac = from_var(mid + half * node)
            x = eye + t[..., None] * dirs
            if directional:
                r = (x - lpos) @ axis
                ldir = axis
                factor = np.ones_like(r)
            else:
                lv = x - lpos
                r = np.linalg.norm(lv, axis=-1)
                ldir = lv / r[..., None]
                factor = 1.0 / (c0 + c1 * r + c2 * r * r)
                if light.kind == "spot" and light.exponent != 0:
                    factor = factor * np.clip(ldir @ axis, 0.0, 1.0) ** light.exponent
            cos_theta = -_dot(dirs, ldir)
            scalar = _phase(cos_theta, medium) * factor * jac * weight * half
            depth = r + t
            if medium.density is not None:
                # Both legs through the field: eye to x, x to the light (or its plane).
                source = x - r[..., None] * axis if directional else np.broadcast_to(lpos, x.shape)
                scalar = scalar * medium.density(x)
                depth = (medium.optical_depth(np.broadcast_to(eye, x.shape), x) +
                         medium.optical_depth(x, source))
            term = scalar[..., None] * np.exp(-sigma_t * depth[..., None])
            if cookie is not None:
                u, v = cookie_uv(light, x)
                if directional:
                    u, v = u - np.floor(u), v - np.floor(v)
                term = term * cookie(u, v)
            total += term
    total *= (sigma_s * intensity)
    return np.where(valid[..., None], total, 0.0)


def in_scattered_radiance(cam, light, medium, scene, panels=4, rows_per_chunk=32, shadows=True):
    """L_in as an array (height, width, 3), row 0 at the bottom, for one light or a list of
    lights (their sum). shadows=False: spheres and floors stop view rays but cast no shadow (what an
    unshadowed method computes)."""
    lights = list(light) if isinstance(light, (list, tuple)) else [light]
    eye, dirs, forward = camera_rays(cam)
    out = np.zeros((cam.height, cam.width, 3))
    for start in range(0, cam.height, rows_per_chunk):
        rows = slice(start, start + rows_per_chunk)
        d = dirs[rows].reshape(-1, 3)
        o = eye[rows].reshape(-1, 3) if cam.parallel else eye
        t_s = surface_distance(o, d, forward, cam, scene)
        acc = np.zeros((d.shape[0], 3))
        for each in lights:
            lo, hi = lit_interval(each, o, d)
            lo = np.maximum(lo, 0.0)
            hi = np.minimum(hi, t_s)
            # Lit pieces: [lo, hi] minus the union of shadow intervals (spheres may overlap).
            pieces = [(lo, hi)]
            occluders = [shadow_interval(each, o, d, centre, radius)
                         for centre, radius in scene.spheres]
            occluders += [floor_shadow_interval(each, o, d, floor) for floor in scene.floors]
            for s0, s1 in (occluders if shadows else []):
                no_shadow = s0 >= s1
                s0 = np.where(no_shadow, np.inf, s0)
                s1 = np.where(no_shadow, np.inf, s1)
                new = []
                for a, b in pieces:
                    new.append((a, np.minimum(b, s0)))
                    new.append((np.maximum(a, s1), b))
                pieces = new
            for a, b in pieces:
                acc += _integrate_pieces(o, d, a, b, each, medium, panels)
        out[rows] = acc.reshape(-1, cam.width, 3)
    return out


def relative_rms_error(image, reference, threshold=0.01):
    """||image - reference|| / ||reference|| over pixels whose reference exceeds threshold*peak."""
    luminance = reference.mean(axis=-1)
    mask = luminance > threshold * luminance.max()
    diff = image[mask] - reference[mask]
    return float(np.sqrt(np.sum(diff ** 2) / np.sum(reference[mask] ** 2))), int(mask.sum())


def energy_error(image, reference):
    return float(abs(image.sum() - reference.sum()) / reference.sum())
