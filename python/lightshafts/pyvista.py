"""Light shafts in PyVista plotters, in PyVista's ``enable_*`` idiom.

    import pyvista as pv
    from lightshafts.pyvista import enable_light_shafts, disable_light_shafts

    plotter = pv.Plotter(off_screen=True, lighting="none")
    plotter.add_mesh(pv.Sphere(center=(0, 3, 0)))
    plotter.add_mesh(pv.Plane(i_size=12, j_size=12, direction=(0, 1, 0)))
    spot = pv.Light(position=(0, 6, 0), focal_point=(0, 0, 0), positional=True, cone_angle=20)
    plotter.add_light(spot)
    enable_light_shafts(plotter, light=spot, quality="interactive",
                        ScatteringCoefficient=0.08, Exposure=12)
    plotter.enable_ssao()                  # PyVista's own passes keep working with the shafts
    plotter.screenshot("shafts.png")

The pass joins the chain of render passes that PyVista keeps for each renderer (its
``RenderPasses``), so PyVista's own passes can be switched on and off in any order around it:
shadows, eye-dome lighting, SSAO, depth of field, blur, SSAA, FXAA and multisampling. While the
shafts are on, the chain is, from the scene outwards: the scene (with PyVista's shadows), the
passes that read the scene's geometry (eye-dome lighting its depth, SSAO its positions and
normals; both write the depth back), the shafts, then the image filters (depth of field, blur,
SSAA), which so filter the shafts too. The shafts need the depth of the picture they are given,
and depth of field and blur write none: inside them the shafts would not be hidden by surfaces.
(PyVista's own order puts SSAO after the image filters: only the shafts' position differs while
they are on, and nothing at all while they are off.)
"""

import pyvista

from . import configure, fit_medium_unless_given, vtkLightShaftPass

__all__ = ["enable_light_shafts", "disable_light_shafts", "get_light_shafts"]

_SHAFTS = "vtkLightShaftPass"
# PyVista's passes that read the scene's geometry: they go inside the shafts.
_READ_GEOMETRY = ("vtkSSAOPass",)


def _render_passes_module():
    """PyVista's render-pass module, taught where the shafts go (once per process)."""
    from pyvista.plotting import render_passes

    chain = getattr(render_passes, "RenderPasses", None)
    if chain is None or not all(hasattr(chain, name) for name in
                                ("_add_pass", "_remove_pass", "_update_passes")) \
            or not isinstance(getattr(render_passes, "POST_PASS", None), list):
        raise RuntimeError(f"lightshafts.pyvista needs PyVista's RenderPasses (PyVista 0.44 to "
                           f"0.49); PyVista {pyvista.__version__} has another render-pass chain")
    if getattr(chain._update_passes, "_lightshafts", False):
        return render_passes
    post = render_passes.POST_PASS
    if _SHAFTS not in post:
        post.insert(post.index("vtkSSAAPass") if "vtkSSAAPass" in post else len(post), _SHAFTS)
    pyvista_update = chain._update_passes

    def _update_passes(self):
        # PyVista builds the chain from its module's order (PRE_PASS + POST_PASS); while this
        # renderer has shafts, that order has the geometry readers before them.
        if _SHAFTS not in self._passes:
            return pyvista_update(self)
        pyvista_order = list(post)
        post[:] = ([name for name in pyvista_order if name in _READ_GEOMETRY] + [_SHAFTS]
                   + [name for name in pyvista_order
                      if name not in _READ_GEOMETRY and name != _SHAFTS])
        try:
            return pyvista_update(self)
        finally:
            post[:] = pyvista_order

    _update_passes._lightshafts = True
    _update_passes.__doc__ = pyvista_update.__doc__
    chain._update_passes = _update_passes
    return render_passes


def _renderer(plotter):
    """The renderer of `plotter`: a pyvista.Plotter's active renderer, or a pyvista.Renderer."""
    renderer = getattr(plotter, "renderer", plotter)
    if not hasattr(renderer, "_render_passes"):
        raise TypeError(f"expected a pyvista.Plotter or pyvista.Renderer, not "
                        f"{type(plotter).__name__}")
    return renderer


def get_light_shafts(plotter):
    """The vtkLightShaftPass of `plotter`'s (active) renderer, or None when the shafts are off."""
    passes = _renderer(plotter)._render_passes._passes.get(_SHAFTS)
    return passes[0] if passes else None


def enable_light_shafts(plotter, light=None, quality=None, method=None, **params):
    """Add volumetric light shafts to `plotter` (a pyvista.Plotter: its active renderer; or a
    pyvista.Renderer) and return the vtkLightShaftPass.

    light: the light whose shafts are drawn (a pyvista.Light or a vtkLight; added to the
    renderer when it is not there yet), or None for the pass's own choice (the renderer's spot
    and point lights). quality: "draft", "interactive" or "final". method: "slices",
    "ray-march", "radial-blur", "analytic", "automatic", "epipolar" or "light-volume". Every
    other keyword is a parameter of vtkLightShaftPass or of its medium (Name=value calls
    SetName(value) on whichever has it; lightshafts.add_light_shafts has the rules, and a new
    pass given no coefficient or exposure chooses them from the scene). Called again
    on the same renderer, it sets up the pass it already has and returns it. The picture changes at the plotter's next render (show, screenshot, render).
    """
    _render_passes_module()
    renderer = _renderer(plotter)
    chain = renderer._render_passes
    if hasattr(chain, "_check_closed"):
        chain._check_closed()  # (PyVista 0.49: a closed plotter's renderer raises)
    if isinstance(light, pyvista.Light) and not any(other is light for other in renderer.lights):
        renderer.add_light(light)  # (PyVista keeps its own list of the renderer's lights)
    shafts = get_light_shafts(renderer)
    added = shafts is None
    if added:
        shafts = vtkLightShaftPass()
        fit_medium_unless_given(shafts, params)
    configure(shafts, renderer, light=light, quality=quality, method=method, **params)
    if added:
        chain._add_pass(shafts)
    return shafts


def disable_light_shafts(plotter):
    """Remove the light shafts from `plotter` (its active renderer) and free their GL objects;
    PyVista's other passes stay as they are. Nothing happens when the shafts are off."""
    renderer = _renderer(plotter)
    shafts = get_light_shafts(renderer)
    if shafts is None:
        return
    _render_passes_module()
    # Its delegate is PyVista's chain, still in use: detach it first. (PyVista 0.49 releases a
    # removed pass's GL objects, delegates included; a shadow baker's maps released so crash
    # its vtkShadowMapPass at the next frame.)
    shafts.SetDelegatePass(None)
    renderer._render_passes._remove_pass(shafts)
    window = renderer.GetRenderWindow()
    if window is not None:
        shafts.ReleaseGraphicsResources(window)  # (PyVista 0.44 releases nothing it removes)
