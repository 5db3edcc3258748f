set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "kappa_damage_vs_surface_energy.png"
set title "kappa_damage against γ (J/m²) (μ = 0.2)" noenhanced
set xlabel "γ (J/m²)" noenhanced
set ylabel "kappa_damage" noenhanced
set grid
set key outside right top noenhanced
set logscale x
set format x '10^{%T}'
plot "kappa_damage_vs_surface_energy.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse, E (Pa) = 8.4e+06", \
     "kappa_damage_vs_surface_energy.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "inhouse, E (Pa) = 8.4e+07", \
     "kappa_damage_vs_surface_energy.dat" index 2 using 1:2:3 with yerrorlines lw 2 title "inhouse, E (Pa) = 8.4e+08"
