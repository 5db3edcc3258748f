set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "kappa_vol_vs_cohesive_stiffness.png"
set title "kappa_vol against k_c (N/m) (μ = 0.2)" noenhanced
set xlabel "k_c (N/m)" noenhanced
set ylabel "kappa_vol" noenhanced
set grid
set key outside right top noenhanced
set logscale x
set format x '10^{%T}'
plot "kappa_vol_vs_cohesive_stiffness.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_e (N/m) = 1e+04", \
     "kappa_vol_vs_cohesive_stiffness.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_e (N/m) = 1e+05", \
     "kappa_vol_vs_cohesive_stiffness.dat" index 2 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_e (N/m) = 1e+06"
