set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "kappa_damage_vs_cohesive_work.png"
set title "kappa_damage against the cohesive work of a pair" noenhanced
set xlabel "cohesive work (J)" noenhanced
set ylabel "kappa_damage" noenhanced
set grid
set key outside right top noenhanced
set logscale x
set format x '10^{%T}'
plot "kappa_damage_vs_cohesive_work.dat" index 0 using 1:2:3 with yerrorbars lw 2 title "inhouse"
