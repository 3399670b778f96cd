"""LightShafts: volumetric light shafts for VTK scenes.

    from lightshafts import vtkLightShaftPass
    shafts = vtkLightShaftPass()
    shafts.GetMedium().SetScatteringCoefficient(0.05)
    renderer.SetPass(shafts)
"""

# The wrapped classes derive from VTK's OpenGL render passes: load those modules first so the
# base classes are registered with VTK's Python wrapping.
import vtkmodules.vtkCommonExecutionModel  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingCore  # noqa: F401

# The two compiled modules: vtkLightShaftsCore (no OpenGL: the medium) and vtkLightShaftsOpenGL
# (the pass and what renders).
from .vtkLightShaftsCore import vtkLightShaftMedium  # noqa: F401
from .vtkLightShaftsOpenGL import (  # noqa: F401
    vtkLightShaftFetchFloor, vtkLightShaftFrameReport, vtkLightShaftPass, vtkLightShaftReference)

__all__ = ["vtkLightShaftPass", "vtkLightShaftMedium", "vtkLightShaftFrameReport",
           "vtkLightShaftReference", "vtkLightShaftFetchFloor", "add_light_shafts", "configure",
           "parameter_owner", "fit_medium_unless_given", "write_png", "show_or_save", "render_converged",
           "refine_while_still"]

# Every method by the name the pass gives it ("slices", "ray-march", ..., "light-volume").
_METHODS = {vtkLightShaftPass.GetMethodName(m): m
            for m in (vtkLightShaftPass.SLICES, vtkLightShaftPass.RAY_MARCH,
                      vtkLightShaftPass.RADIAL_BLUR, vtkLightShaftPass.ANALYTIC,
                      vtkLightShaftPass.AUTOMATIC, vtkLightShaftPass.EPIPOLAR,
                      vtkLightShaftPass.LIGHT_VOLUME)}
_QUALITIES = ("draft", "interactive", "final")


def add_light_shafts(renderer, light=None, quality=None, method=None, **params):
    """Add light shafts to `renderer` in one line and return the vtkLightShaftPass.

        shafts = add_light_shafts(renderer, light=spot, ScatteringCoefficient=0.05, Exposure=40)

    light: the spotlight (a vtkLight; added to the renderer when it is not there yet), or None
    for the renderer's first spotlight. quality: "draft", "interactive" or "final" (applied
    first). method: "slices", "ray-march", "radial-blur", "analytic", "automatic", "epipolar",
    "light-volume" (or the vtkLightShaftPass constant). Every other keyword is a parameter of the
    pass or of its medium (vtkLightShaftMedium: ScatteringCoefficient, PhaseFunction, NoiseAmplitude,
    DensityField, ...): Name=value calls SetName(value) on whichever has it, a tuple or list is
    passed as separate arguments (ScatteringCoefficient=(r, g, b)), a bool switches
    NameOn()/NameOff(). Given no ScatteringCoefficient, AbsorptionCoefficient or Exposure, the
    pass chooses them from the scene at its first frame (vtkLightShaftPass.FitMediumToScene:
    the same picture whatever the scene's size; shafts.GetMedium().GetScatteringCoefficient()
    and shafts.GetExposure() then report them). A pass the renderer already had becomes the
    delegate, so the scene renders as before, with shafts. (PyVista plotters:
    lightshafts.pyvista.enable_light_shafts, which keeps PyVista's own passes working.)
    """
    shafts = vtkLightShaftPass()
    fit_medium_unless_given(shafts, params)
    configure(shafts, renderer, light=light, quality=quality, method=method, **params)
    previous = renderer.GetPass()
    if previous is not None:
        shafts.SetDelegatePass(previous)
    renderer.SetPass(shafts)
    return shafts


# The parameters that set the medium's scale: given any, the pass does not choose it.
_MEDIUM_SCALE = ("ScatteringCoefficient", "AbsorptionCoefficient", "Exposure")


def fit_medium_unless_given(shafts, params):
    """Have `shafts` choose its medium and exposure from the scene (FitMediumToScene) unless
    `params` (keyword parameters, as add_light_shafts takes them) set any of them."""
    if not any(name in params for name in _MEDIUM_SCALE):
        shafts.FitMediumToSceneOn()


def configure(shafts, renderer, light=None, quality=None, method=None, **params):
    """Set up `shafts` (a vtkLightShaftPass) as add_light_shafts describes: the quality preset
    first, then the method, the parameters, and the light (added to `renderer` when it is not
    there yet). Returns `shafts`."""
    if quality is not None:
        if str(quality).lower() not in _QUALITIES:
            raise ValueError(f"quality must be one of {_QUALITIES}, not {quality!r}")
        getattr(shafts, "SetQualityTo" + str(quality).capitalize())()
    if method is not None:
        if isinstance(method, str):
            if method.lower() not in _METHODS:
                raise ValueError(f"method must be one of {tuple(_METHODS)}, not {method!r}")
            method = _METHODS[method.lower()]
        shafts.SetMethod(int(method))
    for name, value in params.items():
        owner = parameter_owner(shafts, name)
        setter = getattr(owner, "Set" + name)
        if isinstance(value, bool) and hasattr(owner, name + "On"):
            getattr(owner, name + ("On" if value else "Off"))()
        elif isinstance(value, (tuple, list)):
            setter(*value)
        else:
            setter(value)
    if light is not None:
        lights = renderer.GetLights()
        if not any(lights.GetItemAsObject(i) is light for i in range(lights.GetNumberOfItems())):
            renderer.AddLight(light)
        shafts.SetLight(light)
    return shafts


def parameter_owner(shafts, name):
    """The object that holds parameter `name` of `shafts` (a vtkLightShaftPass): the pass itself
    (how the shafts are computed) or its medium (vtkLightShaftMedium: what they scatter in).
    TypeError when neither has a Set`name`."""
    for owner in (shafts, shafts.GetMedium()):
        if hasattr(owner, "Set" + name):
            return owner
    raise TypeError(f"neither vtkLightShaftPass nor vtkLightShaftMedium has a parameter {name!r}"
                    f" (no Set{name})")


def render_converged(window, shafts, max_frames=None, progress=None):
    """Render `window` until the still picture of `shafts` (a vtkLightShaftPass) is converged:
    switches its ProgressiveRefinement on (and leaves it on) and renders until
    GetLastFrame().GetRefinementConverged(), at most `max_frames` estimates (default: its
    RefinementFrames, times the frame's GetRefinementSplit() where a still view after frames
    under a budget, or a setting too long for one frame (SplitLongFrames), splits its setting
    among estimates). With ExactFinish on it also waits for
    the exact finish to complete, rendering every 50 ms once the estimates are done.

    `progress`: called after every frame with how far the picture is, a float in [0, 1] that
    never decreases and is 1 after the last frame: the share of the estimates made, or with
    ExactFinish on the share of the picture's pixels already exact. True shows a tqdm
    progress bar instead.

    Returns the number of frames rendered. For offscreen batch renders:

        frames = lightshafts.render_converged(window, shafts, progress=True)
        lightshafts.write_png(window, "still.png")
    """
    import time

    report = _progress_reporter(progress)
    shafts.ProgressiveRefinementOn()
    limit = shafts.GetRefinementFrames() if max_frames is None else int(max_frames)
    frames = estimates = 0
    split = 1
    done = 0.0
    try:
        while estimates < max(limit * split, 1):
            window.Render()
            frames += 1
            # Converged, or nothing to refine (no shafts were computed).
            frame = shafts.GetLastFrame()
            split = frame.GetRefinementSplit() if max_frames is None else 1
            if frame.GetRefinementConverged() or frame.GetRefinementEstimates() == 0:
                break
            if _finishing_only(shafts):
                time.sleep(0.05)  # the finish's threads at work; no estimate was made
            else:
                estimates += 1
            if shafts.GetExactFinish():
                share = frame.GetExactFinishFraction()
            else:
                share = estimates / max(limit * split, 1)
            done = max(done, min(share, 1.0))
            report(done)
        report(1.0)
    finally:
        report(None)
    return frames


def _progress_reporter(progress):
    """A function of the share done (None: the end) for render_converged's `progress`."""
    if progress is True:
        from tqdm import tqdm

        bar = tqdm(total=1000, desc="converging", unit="‰", leave=False)

        def show(share):
            if share is None:
                bar.close()
            else:
                bar.update(int(round(share * 1000)) - bar.n)

        return show
    if progress:
        return lambda share: share is not None and progress(share)
    return lambda share: None


def _finishing_only(shafts):
    """Whether the last frame of `shafts` only showed the exact finish's new tiles: the finish
    runs and no estimate was computed (refinement is done, or the finish just began)."""
    frame = shafts.GetLastFrame()
    return (frame.GetExactFinishState() == vtkLightShaftFrameReport.EXACT_FINISH_RUNNING
            and frame.GetInScatterReused())


def refine_while_still(interactor, shafts):
    """Refine the still view of an interactive window until it is converged: each
    RefinementNeededEvent of `shafts` asks `interactor` for a one-shot timer, whose TimerEvent
    renders once more (never a render inside the pass's own render). Moving the camera starts
    a new picture, refined again once the view rests. Switches ProgressiveRefinement on.
    Returns the two observer tags: (on `shafts`, on `interactor`)."""
    from vtkmodules.vtkCommonCore import vtkCommand

    shafts.ProgressiveRefinementOn()
    pending = []

    def on_refinement_needed(caller, event):
        if not pending:
            # While only the exact finish runs, its threads need the processor time: look
            # for finished tiles ten times a second.
            pending.append(interactor.CreateOneShotTimer(100 if _finishing_only(shafts) else 1))

    def on_timer(caller, event):
        if pending:
            pending.clear()
            interactor.Render()

    return (shafts.AddObserver(vtkLightShaftPass.RefinementNeededEvent, on_refinement_needed),
            interactor.AddObserver(vtkCommand.TimerEvent, on_timer))


def write_png(window, filename):
    """Write what `window` rendered last (its back buffer) to a PNG file."""
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(str(filename))
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def show_or_save(window, output=None, interactive=False):
    """Open an interactive window (needs a display), or render offscreen and write `output`."""
    if interactive:
        import vtkmodules.vtkInteractionStyle  # noqa: F401  (the default interactor style)
        from vtkmodules.vtkRenderingCore import vtkRenderWindowInteractor

        interactor = vtkRenderWindowInteractor()
        interactor.SetRenderWindow(window)
        window.Render()
        interactor.Start()
        return
    window.SetOffScreenRendering(1)
    window.Render()
    if output:
        write_png(window, output)
