set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "kappa_damage_vs_friction.png"
set title "kappa_damage against μ (E (Pa) = 8.4e+07)" noenhanced
set xlabel "μ" noenhanced
set ylabel "kappa_damage" noenhanced
set grid
set key outside right top noenhanced
set logscale x
set format x '10^{%T}'
plot "kappa_damage_vs_friction.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse, γ (J/m²) = 12.15", \
     "kappa_damage_vs_friction.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "inhouse, γ (J/m²) = 121.5", \
     "kappa_damage_vs_friction.dat" index 2 using 1:2:3 with yerrorlines lw 2 title "inhouse, γ (J/m²) = 1215"
