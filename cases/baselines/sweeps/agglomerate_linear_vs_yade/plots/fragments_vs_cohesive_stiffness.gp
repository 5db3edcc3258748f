set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "fragments_vs_cohesive_stiffness.png"
set title "fragments against k_c (N/m)" noenhanced
set xlabel "k_c (N/m)" noenhanced
set ylabel "fragments" noenhanced
set grid
set key outside right top noenhanced
set logscale x
set format x '10^{%T}'
plot "fragments_vs_cohesive_stiffness.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse", \
     "fragments_vs_cohesive_stiffness.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "yade"
