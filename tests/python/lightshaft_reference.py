"""Independent float64 reference for the in-scattered radiance L_in (numpy only).

Computes, for every pixel-centre view ray of a camera, the integral of the model that
vtkLightShaftPass documents:

    L_in = int_0^{t_s} sigma_s p(cos theta) I S(x) A(r) V(x) exp(-sigma_t r) exp(-sigma_t t) dt

for an analytic scene made of spheres (occluders) and finite horizontal floors, lit by one
spotlight. Nothing here uses the pass or VTK's matrices: rays come from the camera's position,
focal point, view-up, view angle and clipping range; surfaces and shadows are exact
(ray-sphere and ray-plane hits; a sphere's shadow is the part of its tangent cone beyond the
tangent circle). The ray is split at every breakpoint (spot-cone entry/exit, shadow entry/exit,
surface) and each smooth piece is integrated by composite Gauss-Legendre quadrature, in the
equiangular variable x = h tan(phi) when A(r) falls off with r.

Conventions shared with the pass: cos theta = -d . (x - light) / r (theta = 0 is forward
scattering), S = cos(angle to the axis)^exponent inside the cone half-angle and 0 outside,
A = 1 / (c0 + c1 r + c2 r^2), image row 0 at the bottom.
"""

from dataclasses import dataclass, field

import numpy as np

ISOTROPIC, HENYEY_GREENSTEIN, RAYLEIGH = 0, 1, 2


@dataclass
class Camera:
    position: tuple
    focal_point: tuple
    view_up: tuple
    view_angle: float  # vertical, degrees (VTK's default)
    clipping_range: tuple
    width: int
    height: int


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


@dataclass
class Medium:
    scattering: tuple
    absorption: tuple = (0.0, 0.0, 0.0)
    phase: int = ISOTROPIC
    anisotropy: float = 0.0


@dataclass
class Scene:
    spheres: list = field(default_factory=list)  # (centre, radius)
    floors: list = field(default_factory=list)  # (height y, xmin, xmax, zmin, zmax)


def _normalize(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def camera_rays(cam):
    """Unit directions (h, w, 3) of the pixel-centre rays, row 0 at the bottom, and the origin."""
    eye = np.asarray(cam.position, float)
    forward = _normalize(np.asarray(cam.focal_point, float) - eye)
    right = _normalize(np.cross(forward, np.asarray(cam.view_up, float)))
    up = np.cross(right, forward)
    tan_half = np.tan(np.radians(cam.view_angle) / 2.0)
    aspect = cam.width / cam.height
    x = (2.0 * (np.arange(cam.width) + 0.5) / cam.width - 1.0) * tan_half * aspect
    y = (2.0 * (np.arange(cam.height) + 0.5) / cam.height - 1.0) * tan_half
    dirs = (x[None, :, None] * right + y[:, None, None] * up + forward)
    return eye, _normalize(dirs), forward


def surface_distance(eye, dirs, forward, cam, scene):
    """Distance to the first surface along each ray, or to the far clipping plane."""
    t = cam.clipping_range[1] / (dirs @ forward)
    for centre, radius in scene.spheres:
        m = eye - np.asarray(centre, float)
        b = dirs @ m
        c = m @ m - radius * radius
        disc = b * b - c
        hit = disc >= 0.0
        t_hit = -b - np.sqrt(np.where(hit, disc, 0.0))
        ok = hit & (t_hit > 0.0) & (t_hit < t)
        t = np.where(ok, t_hit, t)
    for height, xmin, xmax, zmin, zmax in scene.floors:
        dy = dirs[..., 1]
        with np.errstate(divide="ignore", invalid="ignore"):
            t_hit = (height - eye[1]) / dy
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
    dm = dirs @ m
    c2 = cos_half * cos_half
    qa = da * da - c2
    qb = 2.0 * (da * ma - c2 * dm)
    qc = ma * ma - c2 * (m @ m)
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


def light_basis(light):
    """(forward, right, up) of the light's camera as vtkLightShaftPass builds it: view-up is
    world +Y, or +X for a light aiming within ~8 degrees of the Y axis."""
    lpos = np.asarray(light.position, float)
    forward = _normalize(np.asarray(light.focal_point, float) - lpos)
    up0 = np.array([0.0, 1.0, 0.0]) if abs(forward[1]) < 0.99 else np.array([1.0, 0.0, 0.0])
    right = _normalize(np.cross(forward, up0))
    return forward, right, np.cross(right, forward)


def cookie_uv(light, points):
    """Cookie coordinates (u, v) of world points, for the pass's light camera."""
    forward, right, up = light_basis(light)
    d = points - np.asarray(light.position, float)
    depth = d @ forward
    tan_half = np.tan(np.radians(min(light.cone_angle, 89.9)))
    with np.errstate(divide="ignore", invalid="ignore"):
        u = 0.5 * (d @ right) / (depth * tan_half) + 0.5
        v = 0.5 * (d @ up) / (depth * tan_half) + 0.5
    return u, v


def _phase(cos_theta, medium):
    if medium.phase == HENYEY_GREENSTEIN:
        g = medium.anisotropy
        denom = 1.0 + g * g - 2.0 * g * cos_theta
        return (1.0 - g * g) / (4.0 * np.pi * denom ** 1.5)
    if medium.phase == RAYLEIGH:
        return 3.0 / (16.0 * np.pi) * (1.0 + cos_theta ** 2)
    return np.full_like(cos_theta, 1.0 / (4.0 * np.pi))


_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(16)


def _integrate_pieces(eye, dirs, t0, t1, light, medium, panels):
    """Composite Gauss-Legendre of the (visible) integrand over [t0, t1] per ray; returns (n, 3)."""
    lpos = np.asarray(light.position, float)
    axis = _normalize(np.asarray(light.focal_point, float) - lpos)
    c0, c1, c2 = light.attenuation
    intensity = light.intensity * np.asarray(light.color, float)
    sigma_s = np.asarray(medium.scattering, float)
    sigma_t = sigma_s + np.asarray(medium.absorption, float)
    valid = t1 > t0
    t0 = np.where(valid, t0, 0.0)
    t1 = np.where(valid, t1, 0.0)
    m = eye - lpos
    b = dirs @ m
    h = np.sqrt(np.maximum(m @ m - b * b, 0.0))
    equiangular = (c1 != 0.0 or c2 != 0.0)
    if equiangular:
        h = np.maximum(h, 1e-12)
        u0 = np.arctan2(t0 + b, h)
        u1 = np.arctan2(t1 + b, h)
    else:
        u0, u1 = t0, t1
    total = np.zeros(dirs.shape[:-1] + (3,))
    edges = np.linspace(0.0, 1.0, panels + 1)
    for k in range(panels):
        a = u0 + (u1 - u0) * edges[k]
        c = u0 + (u1 - u0) * edges[k + 1]
        half = 0.5 * (c - a)
        mid = 0.5 * (c + a)
        for node, weight in zip(_NODES, _WEIGHTS):
            u = mid + half * node
            if equiangular:
                t = h * np.tan(u) - b
                jac = h / np.cos(u) ** 2
            else:
                t = u
                jac = 1.0
            x = eye + t[..., None] * dirs
            lv = x - lpos
            r = np.linalg.norm(lv, axis=-1)
            ldir = lv / r[..., None]
            cos_axis = np.clip(ldir @ axis, 0.0, 1.0)
            spot = cos_axis ** light.exponent if light.exponent != 0 else np.ones_like(cos_axis)
            cos_theta = -np.sum(dirs * ldir, axis=-1)
            atten = 1.0 / (c0 + c1 * r + c2 * r * r)
            scalar = _phase(cos_theta, medium) * spot * atten * jac * weight * half
            term = scalar[..., None] * np.exp(-sigma_t * (r + t)[..., None])
            if light.cookie is not None:
                term = term * light.cookie(*cookie_uv(light, x))
            total += term
    total *= (sigma_s * intensity)
    return np.where(valid[..., None], total, 0.0)


def in_scattered_radiance(cam, light, medium, scene, panels=4, rows_per_chunk=32, shadows=True):
    """L_in as an array (height, width, 3), row 0 at the bottom. shadows=False: the spheres
    stop view rays but cast no shadow (what an unshadowed method computes)."""
    eye, dirs, forward = camera_rays(cam)
    out = np.zeros((cam.height, cam.width, 3))
    lpos = np.asarray(light.position, float)
    axis = _normalize(np.asarray(light.focal_point, float) - lpos)
    cos_cone = np.cos(np.radians(light.cone_angle))
    for start in range(0, cam.height, rows_per_chunk):
        d = dirs[start:start + rows_per_chunk].reshape(-1, 3)
        t_s = surface_distance(eye, d, forward, cam, scene)
        lo, hi = cone_interval(eye, d, lpos, axis, cos_cone)
        lo = np.maximum(lo, 0.0)
        hi = np.minimum(hi, t_s)
        # Lit pieces: [lo, hi] minus the union of shadow intervals (spheres may overlap).
        pieces = [(lo, hi)]
        for centre, radius in (scene.spheres if shadows else []):
            s0, s1 = sphere_shadow_interval(eye, d, lpos, centre, radius)
            no_shadow = s0 >= s1
            s0 = np.where(no_shadow, np.inf, s0)
            s1 = np.where(no_shadow, np.inf, s1)
            new = []
            for a, b in pieces:
                new.append((a, np.minimum(b, s0)))
                new.append((np.maximum(a, s1), b))
            pieces = new
        acc = np.zeros((d.shape[0], 3))
        for a, b in pieces:
            acc += _integrate_pieces(eye, d, a, b, light, medium, panels)
        out[start:start + rows_per_chunk] = acc.reshape(-1, cam.width, 3)
    return out


def relative_rms_error(image, reference, threshold=0.01):
    """||image - reference|| / ||reference|| over pixels whose reference exceeds threshold*peak."""
    luminance = reference.mean(axis=-1)
    mask = luminance > threshold * luminance.max()
    diff = image[mask] - reference[mask]
    return float(np.sqrt(np.sum(diff ** 2) / np.sum(reference[mask] ** 2))), int(mask.sum())


def energy_error(image, reference):
    return float(abs(image.sum() - reference.sum()) / reference.sum())
