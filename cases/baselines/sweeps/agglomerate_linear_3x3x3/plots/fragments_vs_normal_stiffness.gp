set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "fragments_vs_normal_stiffness.png"
set title "fragments against k_e (N/m) (k_c (N/m) = 100)" noenhanced
set xlabel "k_e (N/m)" noenhanced
set ylabel "fragments" noenhanced
set grid
set key outside right top noenhanced
set logscale x
set format x '10^{%T}'
plot "fragments_vs_normal_stiffness.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse, μ = 0.02", \
     "fragments_vs_normal_stiffness.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "inhouse, μ = 0.2", \
     "fragments_vs_normal_stiffness.dat" index 2 using 1:2:3 with yerrorlines lw 2 title "inhouse, μ = 2"
