"""A gallery of scenes that covers what VTK's own examples draw: surfaces, lines and points,
glyphs, tubes with translucent parts, 2D text, 3D text and billboard labels, cube axes,
textures, several viewports and layers, translucent props with and without depth peeling,
volumes, and VTK's own passes as delegates (shadows, SSAO, outline glow). Each builder fills a
renderer of the window it is given (adding renderers of its own where the scene has several)
and returns the renderer the shafts go into.

test_any_scene.py renders each without the pass, through the pass at zero scattering, and with
a spotlight."""

import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkImageData, vtkPiecewiseFunction, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkElevationFilter, vtkGlyph3D, vtkTubeFilter
from vtkmodules.vtkFiltersSources import (
    vtkArrowSource, vtkConeSource, vtkCubeSource, vtkCylinderSource, vtkLineSource,
    vtkPlaneSource, vtkPointSource, vtkSphereSource)
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingAnnotation import (
    vtkAxesActor, vtkCubeAxesActor, vtkScalarBarActor)
from vtkmodules.vtkRenderingCore import (
    vtkActor, vtkBillboardTextActor3D, vtkColorTransferFunction, vtkFollower, vtkImageActor,
    vtkLight, vtkLightKit, vtkPolyDataMapper, vtkRenderer, vtkTextActor, vtkTextActor3D,
    vtkTexture, vtkVolume, vtkVolumeProperty)
from vtkmodules.vtkRenderingFreeType import vtkVectorText
from vtkmodules.vtkRenderingOpenGL2 import (
    vtkCameraPass, vtkOutlineGlowPass, vtkRenderPassCollection, vtkRenderStepsPass,
    vtkSequencePass, vtkShadowMapPass, vtkSSAOPass)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper
import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401  (text rendering's factories)
import vtkmodules.vtkRenderingFreeType  # noqa: F401


def _actor(source, color=(0.8, 0.8, 0.8), opacity=1.0):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    actor.GetProperty().SetOpacity(opacity)
    return actor


def _floor(renderer, half=4.0, color=(0.7, 0.7, 0.65)):
    plane = vtkPlaneSource()
    plane.SetOrigin(-half, 0.0, -half)
    plane.SetPoint1(half, 0.0, -half)
    plane.SetPoint2(-half, 0.0, half)
    renderer.AddActor(_actor(plane, color))


def _sphere(renderer, centre=(0.0, 1.5, 0.0), radius=0.8, color=(0.9, 0.5, 0.3), opacity=1.0,
            resolution=32):
    sphere = vtkSphereSource()
    sphere.SetCenter(*centre)
    sphere.SetRadius(radius)
    sphere.SetThetaResolution(resolution)
    sphere.SetPhiResolution(resolution)
    actor = _actor(sphere, color, opacity)
    renderer.AddActor(actor)
    return actor


def _camera(renderer, position=(5.0, 4.0, 8.0), focal=(0.0, 1.0, 0.0)):
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*position)
    camera.SetFocalPoint(*focal)
    camera.SetViewUp(0.0, 1.0, 0.0)
    renderer.ResetCameraClippingRange()


def _basic(renderer):
    _floor(renderer)
    _sphere(renderer)
    _camera(renderer)


def surfaces(renderer, window):
    _basic(renderer)
    cube = vtkCubeSource()
    cube.SetCenter(2.0, 0.5, -1.0)
    renderer.AddActor(_actor(cube, (0.3, 0.6, 0.9)))
    return renderer


def lines(renderer, window):
    _floor(renderer)
    for k in range(6):
        line = vtkLineSource()
        line.SetPoint1(-3.0 + k, 0.2, -2.0)
        line.SetPoint2(-2.0 + k, 3.0, 2.0)
        actor = _actor(line, (0.2 + 0.1 * k, 0.8, 0.3))
        actor.GetProperty().SetLineWidth(2.0)
        renderer.AddActor(actor)
    _camera(renderer)
    return renderer


def points(renderer, window):
    _floor(renderer)
    cloud = vtkPointSource()
    cloud.SetCenter(0.0, 1.5, 0.0)
    cloud.SetRadius(1.5)
    cloud.SetNumberOfPoints(400)
    actor = _actor(cloud, (1.0, 1.0, 0.2))
    actor.GetProperty().SetPointSize(4.0)
    actor.GetProperty().SetRepresentationToPoints()
    renderer.AddActor(actor)
    _camera(renderer)
    return renderer


def glyphs(renderer, window):
    _floor(renderer)
    sphere = vtkSphereSource()
    sphere.SetCenter(0.0, 1.5, 0.0)
    sphere.SetThetaResolution(8)
    sphere.SetPhiResolution(8)
    cone = vtkConeSource()
    cone.SetResolution(8)
    glyph = vtkGlyph3D()
    glyph.SetInputConnection(sphere.GetOutputPort())
    glyph.SetSourceConnection(cone.GetOutputPort())
    glyph.SetVectorModeToUseNormal()
    glyph.SetScaleFactor(0.3)
    renderer.AddActor(_actor(glyph, (0.4, 0.9, 0.4)))
    _camera(renderer)
    return renderer


def tubes_with_translucent_parts(renderer, window):
    _floor(renderer)
    for k, opacity in enumerate((1.0, 0.4, 0.6)):
        line = vtkLineSource()
        line.SetPoint1(-2.0 + 2.0 * k, 0.3, -2.0)
        line.SetPoint2(-1.0 + 2.0 * k, 2.5, 2.0)
        tube = vtkTubeFilter()
        tube.SetInputConnection(line.GetOutputPort())
        tube.SetRadius(0.25)
        tube.SetNumberOfSides(16)
        renderer.AddActor(_actor(tube, (0.2, 0.5 + 0.2 * k, 0.9), opacity))
    _camera(renderer)
    return renderer


def text_2d(renderer, window):
    _basic(renderer)
    text = vtkTextActor()
    text.SetInput("Light shafts 2D")
    text.GetTextProperty().SetFontSize(18)
    text.GetTextProperty().SetColor(1.0, 1.0, 0.0)
    text.SetDisplayPosition(10, 10)
    renderer.AddViewProp(text)
    return renderer


def text_3d(renderer, window):
    _floor(renderer)
    text = vtkVectorText()
    text.SetText("VTK")
    actor = _actor(text, (0.9, 0.2, 0.2))
    actor.SetPosition(-1.5, 0.5, 0.0)
    actor.SetScale(1.2, 1.2, 1.2)
    renderer.AddActor(actor)
    _camera(renderer)
    return renderer


def billboard_labels(renderer, window):
    _basic(renderer)
    for k, name in enumerate(("north", "south")):
        label = vtkBillboardTextActor3D()
        label.SetInput(name)
        label.SetPosition(-1.5 + 3.0 * k, 2.5, 0.0)
        label.GetTextProperty().SetFontSize(16)
        label.GetTextProperty().SetColor(0.2, 1.0, 1.0)
        renderer.AddActor(label)
    return renderer


def text_actor_3d(renderer, window):
    _basic(renderer)
    label = vtkTextActor3D()
    label.SetInput("Text3D")
    label.SetPosition(-1.0, 2.6, 0.5)
    label.SetScale(0.03, 0.03, 0.03)
    label.GetTextProperty().SetFontSize(24)
    label.GetTextProperty().SetColor(1.0, 0.6, 0.2)
    renderer.AddActor(label)
    return renderer


def cube_axes(renderer, window):
    _basic(renderer)
    axes = vtkCubeAxesActor()
    axes.SetBounds(-4.0, 4.0, 0.0, 2.5, -4.0, 4.0)
    axes.SetCamera(renderer.GetActiveCamera())
    axes.GetTitleTextProperty(0).SetColor(1.0, 0.3, 0.3)
    axes.GetLabelTextProperty(0).SetColor(1.0, 0.3, 0.3)
    renderer.AddActor(axes)
    renderer.ResetCameraClippingRange()
    return renderer


def axes_actor(renderer, window):
    _basic(renderer)
    axes = vtkAxesActor()
    axes.SetTotalLength(1.5, 1.5, 1.5)
    axes.SetPosition(-2.5, 0.0, 1.0)
    renderer.AddActor(axes)
    renderer.ResetCameraClippingRange()
    return renderer


def _checker_texture():
    image = vtkImageData()
    image.SetDimensions(64, 64, 1)
    colors = vtkUnsignedCharArray()
    colors.SetNumberOfComponents(3)
    i, j = np.meshgrid(np.arange(64), np.arange(64))
    checker = (((i // 8) + (j // 8)) % 2).ravel()
    rgb = np.stack([checker * 230 + 20, 40 + 0 * checker, (1 - checker) * 200 + 30], axis=1)
    colors.SetNumberOfTuples(64 * 64)
    for n, (r, g, b) in enumerate(rgb.astype(int)):
        colors.SetTuple3(n, r, g, b)
    image.GetPointData().SetScalars(colors)
    texture = vtkTexture()
    texture.SetInputData(image)
    texture.InterpolateOn()
    return texture


def textures(renderer, window):
    plane = vtkPlaneSource()
    plane.SetOrigin(-4.0, 0.0, -4.0)
    plane.SetPoint1(4.0, 0.0, -4.0)
    plane.SetPoint2(-4.0, 0.0, 4.0)
    actor = _actor(plane, (1.0, 1.0, 1.0))
    actor.SetTexture(_checker_texture())
    renderer.AddActor(actor)
    _sphere(renderer)
    _camera(renderer)
    return renderer


def translucent_texture(renderer, window):
    # A texture with transparent texels (as 3D text labels are): translucent geometry.
    _basic(renderer)
    image = vtkImageData()
    image.SetDimensions(32, 32, 1)
    colors = vtkUnsignedCharArray()
    colors.SetNumberOfComponents(4)
    colors.SetNumberOfTuples(32 * 32)
    for n in range(32 * 32):
        inside = ((n % 32) // 4 + (n // 32) // 4) % 2
        colors.SetTuple4(n, 255, 200, 40, 255 if inside else 0)
    image.GetPointData().SetScalars(colors)
    texture = vtkTexture()
    texture.SetInputData(image)
    quad = vtkPlaneSource()
    quad.SetOrigin(-1.5, 0.2, 1.5)
    quad.SetPoint1(1.5, 0.2, 1.5)
    quad.SetPoint2(-1.5, 2.7, 1.5)
    actor = _actor(quad, (1.0, 1.0, 1.0))
    actor.SetTexture(texture)
    renderer.AddActor(actor)
    return renderer


def two_viewports(renderer, window):
    renderer.SetViewport(0.0, 0.0, 0.5, 1.0)
    _basic(renderer)
    right = vtkRenderer()
    right.SetViewport(0.5, 0.0, 1.0, 1.0)
    right.SetBackground(0.1, 0.2, 0.3)
    _basic(right)
    _sphere(right, (1.0, 1.0, 1.0), 0.5, (0.3, 0.3, 1.0), opacity=0.5)
    window.AddRenderer(right)
    return renderer


def layers(renderer, window):
    _basic(renderer)
    window.SetNumberOfLayers(2)
    top = vtkRenderer()
    top.SetLayer(1)
    top.SetInteractive(0)
    cone = vtkConeSource()
    top.AddActor(_actor(cone, (0.2, 0.9, 0.2)))
    top.SetActiveCamera(renderer.GetActiveCamera())
    window.AddRenderer(top)
    return renderer


def translucent_blending(renderer, window):
    _floor(renderer)
    _sphere(renderer, (0.0, 1.5, 0.0), 1.0, (0.2, 0.4, 1.0), opacity=0.4)
    _sphere(renderer, (0.6, 1.2, 0.8), 0.8, (1.0, 0.3, 0.2), opacity=0.5)
    _camera(renderer)
    renderer.SetUseDepthPeeling(False)
    return renderer


def translucent_depth_peeling(renderer, window):
    translucent_blending(renderer, window)
    renderer.SetUseDepthPeeling(True)
    renderer.SetMaximumNumberOfPeels(8)
    renderer.SetOcclusionRatio(0.0)
    return renderer


def translucent_background_prop(renderer, window):
    _basic(renderer)
    backdrop = vtkPlaneSource()
    backdrop.SetOrigin(-6.0, 0.0, -4.0)
    backdrop.SetPoint1(6.0, 0.0, -4.0)
    backdrop.SetPoint2(-6.0, 5.0, -4.0)
    renderer.AddActor(_actor(backdrop, (0.9, 0.9, 1.0), opacity=0.3))
    return renderer


def _volume(renderer, position=(1.5, 1.0, 0.5)):
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    mapper = vtkOpenGLGPUVolumeRayCastMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(37.0, 0.0)
    opacity.AddPoint(276.0, 0.5)
    colors = vtkColorTransferFunction()
    colors.AddRGBPoint(37.0, 0.0, 0.4, 1.0)
    colors.AddRGBPoint(276.0, 1.0, 0.9, 0.2)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(colors)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    volume.SetScale(0.06, 0.06, 0.06)
    volume.SetPosition(*position)
    renderer.AddVolume(volume)
    return volume


def volume(renderer, window):
    _basic(renderer)
    _volume(renderer)
    return renderer


def volume_and_translucent_peeled(renderer, window):
    _basic(renderer)
    _volume(renderer)
    _sphere(renderer, (-1.2, 1.0, 1.5), 0.6, (0.2, 1.0, 0.4), opacity=0.4)
    renderer.SetUseDepthPeeling(True)
    renderer.SetUseDepthPeelingForVolumes(True)
    renderer.SetMaximumNumberOfPeels(8)
    renderer.SetOcclusionRatio(0.0)
    return renderer


def _shadow_delegate():
    # As VTK's own shadow example: the baker, then the shadows, in a camera pass.
    shadows = vtkShadowMapPass()
    shadows.GetShadowMapBakerPass().SetResolution(512)
    sequence = vtkSequencePass()
    passes = vtkRenderPassCollection()
    passes.AddItem(shadows.GetShadowMapBakerPass())
    passes.AddItem(shadows)
    sequence.SetPasses(passes)
    camera = vtkCameraPass()
    camera.SetDelegatePass(sequence)
    return camera


def shadow_pass_delegate(renderer, window):
    _basic(renderer)
    renderer.SetPass(_shadow_delegate())
    return renderer


def renderer_shadows(renderer, window):
    _basic(renderer)
    renderer.UseShadowsOn()
    return renderer


def ssao_delegate(renderer, window):
    _basic(renderer)
    ssao = vtkSSAOPass()
    ssao.SetRadius(0.5)
    ssao.SetKernelSize(32)
    ssao.SetDelegatePass(vtkRenderStepsPass())
    renderer.SetPass(ssao)
    return renderer


def outline_glow_delegate(renderer, window):
    _basic(renderer)
    glow = vtkOutlineGlowPass()
    glow.SetDelegatePass(vtkRenderStepsPass())
    renderer.SetPass(glow)
    return renderer


def hidden_line_removal(renderer, window):
    _floor(renderer)
    actor = _sphere(renderer, resolution=16)
    actor.GetProperty().SetRepresentationToWireframe()
    cylinder = vtkCylinderSource()
    cylinder.SetCenter(2.0, 1.0, -1.0)
    wire = _actor(cylinder, (0.3, 1.0, 0.3))
    wire.GetProperty().SetRepresentationToWireframe()
    renderer.AddActor(wire)
    renderer.UseHiddenLineRemovalOn()
    _camera(renderer)
    return renderer


def scalars_and_scalar_bar(renderer, window):
    _floor(renderer)
    sphere = vtkSphereSource()
    sphere.SetCenter(0.0, 1.5, 0.0)
    sphere.SetThetaResolution(32)
    sphere.SetPhiResolution(32)
    elevation = vtkElevationFilter()
    elevation.SetInputConnection(sphere.GetOutputPort())
    elevation.SetLowPoint(0.0, 0.7, 0.0)
    elevation.SetHighPoint(0.0, 2.3, 0.0)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(elevation.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    bar = vtkScalarBarActor()
    bar.SetLookupTable(mapper.GetLookupTable())
    bar.SetWidth(0.12)
    bar.SetHeight(0.6)
    renderer.AddViewProp(bar)
    _camera(renderer)
    return renderer


def parallel_camera(renderer, window):
    _basic(renderer)
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetParallelScale(3.0)
    renderer.ResetCameraClippingRange()
    return renderer


def gradient_background(renderer, window):
    _basic(renderer)
    renderer.GradientBackgroundOn()
    renderer.SetBackground(0.1, 0.1, 0.2)
    renderer.SetBackground2(0.5, 0.6, 0.9)
    return renderer


def fxaa(renderer, window):
    _basic(renderer)
    _sphere(renderer, (1.5, 0.6, 1.0), 0.5, (0.3, 0.9, 0.9), opacity=0.5)
    renderer.UseFXAAOn()
    return renderer


def light_kit(renderer, window):
    _basic(renderer)
    kit = vtkLightKit()
    kit.AddLightsToRenderer(renderer)
    return renderer


def followers(renderer, window):
    _basic(renderer)
    text = vtkVectorText()
    text.SetText("follow")
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(text.GetOutputPort())
    follower = vtkFollower()
    follower.SetMapper(mapper)
    follower.SetPosition(-1.0, 2.8, 0.0)
    follower.SetScale(0.4, 0.4, 0.4)
    follower.SetCamera(renderer.GetActiveCamera())
    renderer.AddActor(follower)
    return renderer


def image_slice(renderer, window):
    _floor(renderer)
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-20, 20, -20, 20, 0, 0)
    source.Update()
    image = vtkImageActor()
    image.GetMapper().SetInputConnection(source.GetOutputPort())
    image.SetScale(0.08, 0.08, 0.08)
    image.SetPosition(0.0, 1.6, -1.0)
    image.GetProperty().SetColorWindow(200.0)
    image.GetProperty().SetColorLevel(160.0)
    renderer.AddActor(image)
    _camera(renderer)
    return renderer


def arrows_and_polydata(renderer, window):
    _floor(renderer)
    arrow = vtkArrowSource()
    actor = _actor(arrow, (1.0, 0.4, 0.7))
    actor.SetPosition(-1.0, 1.0, 0.0)
    actor.SetScale(2.0, 2.0, 2.0)
    renderer.AddActor(actor)
    # Hand-made polydata: a fan of triangles with per-point colours.
    pts = vtkPoints()
    cells = vtkCellArray()
    colors = vtkUnsignedCharArray()
    colors.SetNumberOfComponents(3)
    pts.InsertNextPoint(1.5, 2.0, 0.0)
    colors.InsertNextTuple3(255, 255, 255)
    for k in range(9):
        angle = k * np.pi / 4.0
        pts.InsertNextPoint(1.5 + np.cos(angle), 2.0 + np.sin(angle), 0.0)
        colors.InsertNextTuple3(int(127 + 127 * np.cos(angle)), 80, int(127 + 127 * np.sin(angle)))
    for k in range(8):
        cells.InsertNextCell(3)
        cells.InsertCellPoint(0)
        cells.InsertCellPoint(k + 1)
        cells.InsertCellPoint(k + 2)
    fan = vtkPolyData()
    fan.SetPoints(pts)
    fan.SetPolys(cells)
    fan.GetPointData().SetScalars(colors)
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(fan)
    fan_actor = vtkActor()
    fan_actor.SetMapper(mapper)
    renderer.AddActor(fan_actor)
    _camera(renderer)
    return renderer


def headlight_only(renderer, window):
    # No light of the scene's own: VTK adds its headlight; the spotlight is added by the test.
    _basic(renderer)
    return renderer


def spot_already_in_scene(renderer, window):
    _basic(renderer)
    spot = vtkLight()
    spot.SetPositional(True)
    spot.SetPosition(0.0, 6.0, 0.0)
    spot.SetFocalPoint(0.0, 0.0, 0.0)
    spot.SetConeAngle(30.0)
    renderer.AddLight(spot)
    return renderer


GALLERY = {
    "surfaces": surfaces,
    "lines": lines,
    "points": points,
    "glyphs": glyphs,
    "tubes with translucent parts": tubes_with_translucent_parts,
    "2D text": text_2d,
    "3D text": text_3d,
    "billboard labels": billboard_labels,
    "text actor 3D": text_actor_3d,
    "cube axes": cube_axes,
    "axes actor": axes_actor,
    "texture": textures,
    "texture with transparent texels": translucent_texture,
    "two viewports": two_viewports,
    "layers": layers,
    "translucent, blending": translucent_blending,
    "translucent, depth peeling": translucent_depth_peeling,
    "translucent background prop": translucent_background_prop,
    "volume": volume,
    "volume and translucent, peeled together": volume_and_translucent_peeled,
    "VTK's shadow passes as delegate": shadow_pass_delegate,
    "the renderer's own shadows": renderer_shadows,
    "SSAO as delegate": ssao_delegate,
    "outline glow as delegate": outline_glow_delegate,
    "hidden line removal": hidden_line_removal,
    "scalars and scalar bar": scalars_and_scalar_bar,
    "parallel camera": parallel_camera,
    "gradient background": gradient_background,
    "FXAA": fxaa,
    "light kit": light_kit,
    "followers": followers,
    "image slice": image_slice,
    "arrows and coloured polydata": arrows_and_polydata,
    "headlight only": headlight_only,
    "a spotlight in the scene": spot_already_in_scene,
}
