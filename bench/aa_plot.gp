# make bench-aa's plot (bench/aa.sh): edge error against seconds per
# frame, log-log, one line per pattern and output; solid: the worst of the
# listed angles (lattice also: listed and mirrored, dotted), dashed: the
# worst over the sweep of directions.
# raw: "pattern M output s listed_worst at mirrored_worst at sweep_worst at
# ..." (aa.sh)
set terminal svg size 820,520 font "sans,12" background rgb "white"
set output out
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "seconds per frame (640x480, in-process)"
set ylabel "per-row RMS edge error, px"
set title "glsplay anti-aliasing: edge error against time (make bench-aa); labels: samples M"
set key outside right top box font ",10"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set arrow from graph 0, first 1.0/256 to graph 1, first 1.0/256 nohead dt 3 lc rgb "#888888"
set label "1/256 px" at graph 0.01, first 1.0/256 * 1.15 tc rgb "#666666"
set arrow from graph 0, first 1.0/2048 to graph 1, first 1.0/2048 nohead dt 3 lc rgb "#888888"
set label "1/2048 px" at graph 0.01, first 1.0/2048 * 1.15 tc rgb "#666666"
sel(p, o) = sprintf("< awk '$1 == \"%s\" && $3 == \"%s\"' %s | sort -k2,2n", p, o, raw)
plot \
  sel("lattice", "pfm") u 4:5 w lp lw 2 pt 7 lc rgb "#1f77b4" t "lattice, float: listed angles", \
  sel("lattice", "pfm") u 4:7 w lp lw 1 dt 4 pt 4 lc rgb "#1f77b4" t "lattice, float: listed + mirrored", \
  sel("lattice", "pfm") u 4:9 w lp lw 2 dt 2 pt 6 lc rgb "#1f77b4" t "lattice, float: sweep", \
  sel("lattice", "png16") u 4:5 w lp lw 1 pt 5 lc rgb "#17becf" t "lattice, 16-bit: listed", \
  sel("lattice", "png8") u 4:5 w lp lw 1 pt 9 lc rgb "#9467bd" t "lattice, 8-bit: listed", \
  sel("grid", "pfm") u 4:5 w lp lw 2 pt 7 lc rgb "#d62728" t "grid, float: listed angles", \
  sel("grid", "pfm") u 4:9 w lp lw 2 dt 2 pt 6 lc rgb "#d62728" t "grid, float: sweep", \
  sel("stratified", "pfm") u 4:5 w lp lw 2 pt 7 lc rgb "#2ca02c" t "stratified, float: listed angles", \
  sel("stratified", "pfm") u 4:9 w lp lw 2 dt 2 pt 6 lc rgb "#2ca02c" t "stratified, float: sweep", \
  sel("lattice", "pfm") u 4:5:2 w labels offset 0.8,0.6 font ",9" tc rgb "#1f77b4" notitle
