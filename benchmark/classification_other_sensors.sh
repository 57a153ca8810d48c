#!/bin/sh
# Copyright (c) 2026 Sigmoid_neighborhoods contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The classifier on the labeled sets of other sensors (../shared/data/labeled/README.md): a drone
# photogrammetry survey, a ground-vehicle lidar scan and an IGN LiDAR HD tile of another region, each
# split in space into two files of diagonal quadrants (benchmark/split_labeled.py), trained on one and
# tested on the other; the six IGN tiles of the package's own round tested on the other region; and
# the package's own split of the six tiles (west -> east).
# Each condition is three `classify experiment` runs in ORDERS feature orders, without graph-cut:
#   chosen: CGAL's generator (A) and the candidate sets with scales in metres, each at the first scale
#           that --choose-scales picks for it on the training file (D the default set; M, MP, MS the
#           shorter ones);
#   fixed:  the default set at the fixed 0.5 m of the models trained before the choice (D_05);
#   equal:  the default set with equal weights instead of the sigmoid's (DE, multiscale for
#           multiscale-sigmoid), at its chosen scale: the sigmoid weights' share.
# benchmark/other_sensors_table.py gathers the mean IoU, per class IoU and times.
# usage: benchmark/classification_other_sensors.sh TOOL OUT_DIR [ORDERS] [CONDITION...]
#   e.g. benchmark/classification_other_sensors.sh build/tools/sigmoid-neighborhoods/sigmoid-neighborhoods results/sensors 10
#   CONDITION: drone, vehicle, region, transfer, ign (default: all five)
set -eu
tool=$1
out=$2
orders=${3:-10}
shift $(( $# < 3 ? $# : 3 ))
conditions=${*:-drone vehicle region transfer ign}
here=$(dirname "$0")
labeled=${SN_LABELED:-$here/../../shared/data/labeled}
python=/usr/bin/python3
[ -d "$labeled" ] || { echo "no labeled data in $labeled: nothing to do"; exit 0; }
mkdir -p "$out/files"
f=$out/files

chosen_sets="A=cgal;D=cgal-metric,multiscale-sigmoid,pyramid;M=cgal-metric;MP=cgal-metric,pyramid;MS=cgal-metric,multiscale-sigmoid"
fixed_sets="D_05=cgal-metric,multiscale-sigmoid,pyramid"
equal_sets="DE=cgal-metric,multiscale,pyramid"

split() { # input, output stem, split options
  [ -s "$2_a.$3" ] && return
  input=$1 stem=$2 extension=$3
  shift 3
  "$python" "$here/split_labeled.py" "$input" "${stem}_a.$extension" "${stem}_b.$extension" "$@"
}

run() { # condition, train files, test files, options...
  condition=$1 train=$2 test=$3
  shift 3
  for kind in chosen fixed equal; do
    dir=$out/$condition-$kind
    [ -s "$dir/runs.csv" ] && { echo "$condition $kind: done before"; continue; }
    case $kind in
      chosen) sets=$chosen_sets choose=--choose-scales ;;
      fixed) sets=$fixed_sets choose= ;;
      equal) sets=$equal_sets choose=--choose-scales ;;
    esac
    start=$(date +%s)
    "$tool" classify experiment -o "$dir" --train "$train" --test "$test" --sets "$sets" --orders "$orders" \
      --cv-orders 0 --graphcut 0 $choose "$@" > "$dir.log" 2>&1 ||
      { echo "$condition $kind failed: $(tail -1 "$dir.log")"; exit 1; }
    echo "$condition $kind: $(( $(date +%s) - start )) s"
  done
}

for condition in $conditions; do
  case $condition in
    drone) # the buildings stand in one corner: quadrants about their median, so that both files hold some
      [ -s "$f/drone.las" ] || "$(dirname "$tool")/../../examples/las_copy_example" "$labeled/odm_brighton_small.laz" "$f/drone.las"
      split "$f/drone.las" "$f/drone" las --center-class 6
      run drone "$f/drone_a.las" "$f/drone_b.las" --labels ground=2,low_vegetation=3,building=6 ;;
    vehicle) # quadrants about the sensor; fence (595 points) and mud (100) lie in one file only: left out
      split "$labeled/rellis3d_000104.ply" "$f/vehicle" ply --center 0 0
      run vehicle "$f/vehicle_a.ply" "$f/vehicle_b.ply" \
        --labels grass=3,tree=4,bush=19,concrete=23,person=17,puddle=31 --orientation viewpoint --viewpoint 0 0 0 ;;
    region)
      split "$labeled/ign_lidarhd_myria3d_870000_6618000.las" "$f/region" las
      run region "$f/region_a.las" "$f/region_b.las" --labels other=1,ground=2,building=6 ;;
    transfer) # the six tiles' vegetation and other classes against the region's class 1, which holds its vegetation
      tiles=$(ls "$labeled"/ign_lidarhd_7*.las | paste -sd, -)
      run transfer "$tiles" "$labeled/ign_lidarhd_myria3d_870000_6618000.las" --labels other=1+3+4+5+64,ground=2,building=6 ;;
    ign) # the split of the labeled README: the western 2 x 2 tiles against the eastern column
      west=$(ls "$labeled"/ign_lidarhd_7705[05]_*.las | paste -sd, -)
      east=$(ls "$labeled"/ign_lidarhd_77060_*.las | paste -sd, -)
      run ign "$west" "$east" ;;
    *) echo "unknown condition $condition"; exit 2 ;;
  esac
done
