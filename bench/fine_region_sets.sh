# The --set options of the coarse-graining study's fine region around the knife's path
# (docs/coarse-graining.md; cases/knife_bed/coarse_graining.prm's knife): the whole bed's length
# in x, |y| < HALF_WIDTH, from 0.03 m above the floor to the fill's top; sourced by
# bench/multi_level.sh and bench/replay_life.sh, so that the real-size beds of both are one set:
#   fine_region_sets FACTOR HALF_WIDTH STEP LAYERS POURS   (fills the array fine_sets)
fine_region_sets() {
  fine_sets=(--set "Particles/Coarse graining/Fine region min=-0.97, -$2, 0.03"
             --set "Particles/Coarse graining/Fine region max=0.97, $2, 0.85"
             --set "Particles/Coarse graining/Fine region factor=$1"
             --set "Particles/Coarse graining/Fine region step=$3"
             --set "Particles/Coarse graining/Fine region layer thickness=$4"
             --set "Particles/Coarse graining/Fine region pours=$5")
}
