#!/usr/bin/env bash
# Reproduces a measured figure of the docs: runs one of the measurement scripts offscreen
# (Xvfb) against the build in build/, writing into docs/ unless told otherwise.
#
#   tools/measure.sh accuracy          # slices vs the float64 reference (docs/accuracy.md)
#   tools/measure.sh quality-controls  # each speed/error control (docs/quality-controls.md)
#   tools/measure.sh benchmark         # every method's settings, three scenes (docs/benchmark.md)
#   tools/measure.sh light-kinds       # per light kind and several lights (docs/light-kinds.md)
#   tools/measure.sh refinement        # a still view's progressive refinement (docs/refinement.md)
#   tools/measure.sh budget            # the frame budget on a camera path, then refinement
#                                      # (docs/budget.md)
#   tools/measure.sh refinement-floor  # what the refined picture's floor is made of
#                                      # (docs/refinement-floor.md; about 5 min)
#   tools/measure.sh refinement-filters  # refinement with blur and interleaving, estimate by
#                                      # estimate (docs/refinement-filters.md; about 3 min)
#   tools/measure.sh exact-finish      # a still view with and without the exact finish after
#                                      # the camera stops (docs/exact-finish.md; --scene sphere:
#                                      # docs/exact-finish-sphere.md; about 1 min each)
#   tools/measure.sh still-final       # the Final preset in a still view after frames under a
#                                      # budget, whole or split among estimates
#                                      # (docs/still-final.md; about 2 min)
#   tools/measure.sh any-scene         # the one-liner's medium at three scales, and the far
#                                      # plane moved (docs/any-scene.md; seconds)
#   tools/measure.sh surface-light     # what ShadowSurfaces costs on the window scene
#                                      # (docs/lights-and-cookies.md; about 1 min)
#   tools/measure.sh reprojection      # what carrying the picture to the next camera costs
#                                      # (docs/reprojection.md)
#   tools/measure.sh resolution-cost   # how the budget's settings' time follows the resolution
#                                      # (the cost model's exponents; docs/budget.md)
#   tools/measure.sh medium-field      # a density field's cost against the homogeneous
#                                      # medium (docs/medium-field.md; about 1 min)
#   tools/measure.sh medium-field-pareto  # each method through a plume: speed against
#                                      # error (docs/medium-field.md; about 2 min)
#   tools/measure.sh field-still       # a still view refining the light leg's table through
#                                      # random fields (docs/medium-field.md; about 1 min)
#   tools/measure.sh field-still-cost  # a converged still frame through a field against the
#                                      # homogeneous medium (docs/medium-field.md; 1 min)
#   tools/measure.sh field-error-model # TargetError through a density field: the field
#                                      # factors' calibration (seed 11) and validation (seed
#                                      # 12) (docs/medium-field.md; about 30 min)
#   tools/measure.sh translucent       # translucent casters' cost per layer
#                                      # (docs/translucent-cost.md; about 3 min)
#   tools/measure.sh camera-leg        # translucent props in view per layer, and a volume
#                                      # (docs/translucent-cost.md; about 5 min)
#   tools/measure.sh volume-figures    # the camera leg's and volumes' figures against the
#                                      # reference (docs/translucent-and-volumes.md; 1 min)
#   tools/measure.sh worst-corners     # the slider corners (docs/robustness.md)
#   tools/measure.sh random-scenes     # 50 random scenes: presets, methods, targets, the
#                                      # fitted ladder (TargetError's cost against the oracle)
#                                      # (docs/random-scenes.md; about 20 minutes on 2 cores)
#   tools/measure.sh random-scenes-downsampled  # the same scenes, reduced-resolution settings
#                                      # (docs/downsampled/random-scenes.md; about 30 min)
#   tools/measure.sh random-scenes-epipolar  # the same scenes, EPIPOLAR's settings
#                                      # (docs/epipolar/random-scenes.md)
#   tools/measure.sh random-scenes-light-volume  # the same scenes, LIGHT_VOLUME's settings
#                                      # (docs/light-volume/random-scenes.md)
#   tools/measure.sh error-model       # the TargetError model's training run and fit
#                                      # (docs/error-model.md, plugin/core/vtkLightShaftErrorModelTable.h)
#   tools/measure.sh error-model-add SETTING...  # the same for settings added to the ladder
#                                      # only (the others keep their training rows)
#   tools/measure.sh reference-speed   # the float64 reference's time against the pass's frame
#   tools/measure.sh responsiveness    # the exact finish's stop after 1,000 random changes, the
#                                      # reference's abort (docs/robustness.md; about 4 min)
#   tools/measure.sh frame-bound       # four spotlights at each method's sampling maxima: the
#                                      # whole frame, and split among frames (docs/robustness.md)
#   tools/measure.sh fixed-cost        # a frame's cost besides its integral, a few random scenes
#   tools/measure.sh mpi-scaling       # the shafts' work divided among ParaView's MPI
#                                      # processes, np 1, 2, 4 (docs/paraview-mpi-scaling.md;
#                                      # about 3 min)
#   tools/measure.sh pytest TEST...    # a test, printing what it measured (-s)
#
# Extra arguments go to the script (e.g. tools/measure.sh random-scenes --scenes 5).
# Long runs show a progress bar on stderr (stdout and the files written are unchanged);
# LIGHTSHAFTS_NO_PROGRESS=1 hides it.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -f build/CMakeCache.txt ]; then
  echo "build/ not found: run tools/quickstart.sh first" >&2
  exit 2
fi
python_dir=$(sed -n 's/^LIGHTSHAFTS_PYTHON_DESTINATION:STRING=//p' build/CMakeCache.txt)
export PYTHONPATH="$PWD/build/$python_dir${PYTHONPATH:+:$PYTHONPATH}"
run() {
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" /usr/bin/python3 "$@"
}
what=${1:-}
shift || true
case "$what" in
  accuracy) run tests/measure_accuracy.py --output docs/accuracy.md "$@" ;;
  quality-controls) run tests/benchmarks/quality_controls.py --output docs/quality-controls.md "$@" ;;
  benchmark) run tests/benchmarks/benchmark.py --output-dir docs "$@" ;;
  light-kinds) run tests/benchmarks/light_kinds.py --output-dir docs "$@" ;;
  refinement) run tests/benchmarks/refinement.py --output-dir docs "$@" ;;
  exact-finish) run tests/benchmarks/exact_finish.py --output-dir docs "$@" ;;
  refinement-floor) run tests/benchmarks/refinement_floor.py --output-dir docs "$@" ;;
  refinement-filters) run tests/benchmarks/refinement_filters.py --output-dir docs "$@" ;;
  budget) run tests/benchmarks/budget.py --output-dir docs "$@" ;;
  still-final) run tests/benchmarks/still_final.py --output-dir docs "$@" ;;
  any-scene) run tests/benchmarks/any_scene.py "$@" ;;
  surface-light) run tests/benchmarks/surface_light_cost.py "$@" ;;
  reprojection) run tests/benchmarks/reprojection_bound.py --output docs/reprojection.md "$@" ;;
  resolution-cost) run tests/benchmarks/resolution_cost.py "$@" ;;
  medium-field) run tests/benchmarks/medium_field_cost.py "$@" ;;
  medium-field-pareto) run tests/benchmarks/medium_field_pareto.py "$@" ;;
  field-still) run tests/benchmarks/field_still_refinement.py "$@" ;;
  field-still-cost) run tests/benchmarks/field_still_frame_cost.py "$@" ;;
  field-error-model)
    run tests/benchmarks/field_error_model.py --seed 11 --scenes 16 "$@"
    run tests/benchmarks/field_error_model.py --seed 12 --scenes 16 "$@" ;;
  translucent) run tests/benchmarks/translucent_cost.py "$@" ;;
  camera-leg) run tests/benchmarks/camera_leg_cost.py "$@" ;;
  volume-figures) run tests/benchmarks/volume_figures.py "$@" ;;
  worst-corners) run tests/benchmarks/worst_corners.py "$@" ;;
  random-scenes)
    run tests/benchmarks/random_scenes.py --validation --seed 0 --scenes 50 --max-height 720 \
      --frames 1 --output-dir docs "$@" ;;
  random-scenes-downsampled)
    run tests/benchmarks/random_scenes.py --downsampled --seed 0 --scenes 50 --max-height 720 \
      --frames 3 --output-dir docs/downsampled "$@" ;;
  random-scenes-light-volume)
    run tests/benchmarks/random_scenes.py --light-volume --seed 0 --scenes 50 --max-height 720 \
      --frames 3 --output-dir docs/light-volume "$@" ;;
  random-scenes-epipolar)
    run tests/benchmarks/random_scenes.py --epipolar --seed 0 --scenes 50 --max-height 720 \
      --frames 3 --output-dir docs/epipolar "$@" ;;
  error-model|error-model-add)
    # Training seeds 8 and 9 (the validation above is seed 0), then the fit and a rebuild.
    # error-model-add SETTING...: only those settings of the ladder are run; the others keep
    # their rows of docs/error-model-training.csv.
    training=$(mktemp -d)
    mkdir -p "$training/8" "$training/9"
    previous=()
    only=()
    if [ "$what" = error-model-add ]; then
      cp docs/error-model-training.csv "$training/previous.csv"
      previous=(--previous "$training/previous.csv")
      only=(--settings "$@")
      set --
    fi
    run tests/benchmarks/random_scenes.py --ladder --seed 8 --scenes 30 --max-height 720 \
      --frames 0 --output-dir "$training/8" "${only[@]}" "$@"
    run tests/benchmarks/random_scenes.py --ladder --seed 9 --scenes 25 --max-height 720 \
      --frames 0 --output-dir "$training/9" "${only[@]}" "$@"
    run tests/benchmarks/fit_error_model.py "$training/8/random-scenes.csv" \
      "$training/9/random-scenes.csv" "${previous[@]}"
    cmake --build build > /dev/null ;;
  reference-speed) run tests/benchmarks/reference_speed.py "$@" ;;
  responsiveness) run tests/benchmarks/responsiveness.py "$@" ;;
  frame-bound) run tests/benchmarks/frame_bound.py "$@" ;;
  fixed-cost) run tests/benchmarks/fixed_cost.py "$@" ;;
  mpi-scaling) run tests/benchmarks/paraview_mpi_table.py "$@" ;;
  pytest) run -m pytest -p no:cacheprovider -q -s "$@" ;;
  *)
    sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p}' "$0"  # the header comment
    exit 2 ;;
esac
