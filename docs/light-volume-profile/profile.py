"""Where LIGHT_VOLUME's time goes on this CPU renderer: the README's window scene at 1280x720,
median of 8 frames (camera nudged between them, each finished), with the crossings' shader
as built, reduced to writing zero (LV_TRIVIAL: the mesh's rasterisation without the
integrals), and with the mesh collapsed to a point (LV_DEGENERATE: no fragments; what is
left is the shadow map, the resolve, the plain frame and the composite).

Needs instrumentation.patch applied and built (not kept in the plugin):
    git apply docs/light-volume-profile/instrumentation.patch && cmake --build build
    PYTHONPATH=build/lib/python3.11/dist-packages xvfb-run -a -s "-noreset" \
        /usr/bin/python3 docs/light-volume-profile/profile.py
"""
import os
import statistics
import subprocess
import sys
import time

MODES = [("as built", ""), ("crossings write zero", "LV_TRIVIAL"),
         ("mesh collapsed", "LV_DEGENERATE"), ("no pass", "NO_PASS")]


def measure(cells, mode):
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
    import lightshafts
    from lightshafts import scenes, vtkLightShaftPass
    renderer = vtkRenderer()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(1280, 720)
    window.AddRenderer(renderer)
    scenes.window_room(renderer)
    if mode != "NO_PASS":  # "-": as built
        shafts = lightshafts.add_light_shafts(renderer, ScatteringCoefficient=0.05, Exposure=40)
        shafts.SetMethod(vtkLightShaftPass.LIGHT_VOLUME)
        shafts.SetLightVolumeResolution(cells)
    camera = renderer.GetActiveCamera()
    window.Render()
    window.WaitForCompletion()
    times = []
    for frame in range(8):
        camera.Azimuth(0.01 if frame % 2 else -0.01)
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


if __name__ == "__main__":
    if len(sys.argv) == 3:
        print(f"{1000 * measure(int(sys.argv[1]), sys.argv[2]):.0f}")
        sys.exit(0)
    print("| cells | " + " | ".join(name for name, _ in MODES) + " |")
    print("|---:|" + "---:|" * len(MODES))
    for cells in (256, 1024):
        row = []
        for _, mode in MODES:
            env = dict(os.environ, LV_MODE=mode if mode != "NO_PASS" else "")
            out = subprocess.run([sys.executable, __file__, str(cells), mode or "-"], env=env,
                                 capture_output=True, text=True, check=True).stdout
            row.append(out.strip().splitlines()[-1] + " ms")
        print(f"| {cells} | " + " | ".join(row) + " |")
    for mode in ("LV_TRIVIAL", ""):  # all the mesh's fragments; those the shader keeps
        env = dict(os.environ, LV_MODE=mode, LV_COUNT="1")
        err = subprocess.run([sys.executable, __file__, "256", mode or "-"], env=env,
                             capture_output=True, text=True, check=True).stderr
        print(mode or "as built", [line for line in err.splitlines() if "fragments" in line][-1])
