# What each end-of-life criterion measures, on a worn cross-section of the 30 mm chisel knife
# (docs/lifetime.md, "Criteria a fitter gauges"). Made from a run of the edge-concentrated
# analytic rate:
#   build/abrade run tests/lifetime/analytic_edge.prm --output edge --set "Lifetime/Maximum depth=0" \
#       --set "Lifetime/Maximum edge recession=0.02" --set "Lifetime/Minimum plate thickness=0.02"
#   gnuplot -e "run='edge'" docs/lifetime/criteria.gp      (writes criteria.png here)
if (!exists("run")) run = 'edge'
set terminal pngcairo size 1000,700 font ',11'
set output 'criteria.png'
set size ratio -1
set xlabel 'y [mm] (across the plate)'
set ylabel 'z [mm] (up from the design edge)'
set key outside right top
set grid
f = run.'/part/profile_0.50.csv'
stats f nooutput
last = STATS_blocks - 2  # (the file ends with the blank lines of a block)
# the last update's section: its lowest point and its width at the gauge height (70 mm)
stats f index last using (($3 < $5 ? $3 : $5)*1000) name 'Z' nooutput
h = 70.0
stats f index last using (($3-h/1000)*($5-h/1000) <= 0 ? 1000*($2 + ($4-$2)*(h/1000-$3)/($5-$3)) : 1/0) name 'Y' nooutput
set arrow 1 from 0,0 to 0,Z_min heads lw 2 lc rgb 'dark-violet'
set label 1 sprintf(" edge recession %.1f mm\n (height gauge on the edge)", Z_min) at 1,Z_min/2 tc rgb 'dark-violet'
set arrow 2 from Y_min,h to Y_max,h heads lw 2 lc rgb 'dark-green'
set label 2 sprintf('plate thickness %.1f mm (calipers, %g mm up)', Y_max-Y_min, h) at -38,h+4 tc rgb 'dark-green'
# the depth below the design: the distance from the worn surface to the nearest design surface;
# at the worn tip (0, Z) the nearest design face is a bevel, through (0, 0) and (15, 40) mm
L2 = 15.0**2 + 40.0**2
d = 15.0*Z_min/sqrt(L2)
set arrow 3 from 0,Z_min to 600.0*Z_min/L2, 1600.0*Z_min/L2 heads lw 2 lc rgb 'red'
set label 3 sprintf("depth below the design %.1f mm\n(normal to the nearest design face)", d) at 8,Z_min+2 tc rgb 'red'
set label 4 "worn mass: the volume between\nthe design and the worn surface\n(the whole part, x the density)" at 18,60 tc rgb 'gray30'
set xrange [-40:40]
set yrange [-3:95]
$design << EOD
15 95
15 40
0 0
-15 40
-15 95
EOD
plot $design with lines lw 2 lc rgb 'gray50' title 'design', \
     f index last using ($2*1000):($3*1000):(($4-$2)*1000):(($5-$3)*1000) with vectors nohead lw 2 lc rgb 'black' title sprintf('worn, update %d', last+1)
