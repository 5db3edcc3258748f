set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "kappa_vol_vs_surface_energy.png"
set title "kappa_vol against γ (J/m²)" noenhanced
set xlabel "γ (J/m²)" noenhanced
set ylabel "kappa_vol" noenhanced
set grid
set key outside right top noenhanced
set logscale x
set format x '10^{%T}'
plot "kappa_vol_vs_surface_energy.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse", \
     "kappa_vol_vs_surface_energy.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "lammps"
