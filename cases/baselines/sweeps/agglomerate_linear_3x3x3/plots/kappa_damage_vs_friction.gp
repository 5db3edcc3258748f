set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "kappa_damage_vs_friction.png"
set title "kappa_damage against μ (k_e (N/m) = 1e+05)" noenhanced
set xlabel "μ" noenhanced
set ylabel "kappa_damage" noenhanced
set grid
set key outside right top noenhanced
set logscale x
set format x '10^{%T}'
plot "kappa_damage_vs_friction.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_c (N/m) = 10", \
     "kappa_damage_vs_friction.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_c (N/m) = 100", \
     "kappa_damage_vs_friction.dat" index 2 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_c (N/m) = 1000"
