set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "kappa_damage_vs_cohesive_stiffness.png"
set title "kappa_damage against k_c (N/m)" noenhanced
set xlabel "k_c (N/m)" noenhanced
set ylabel "kappa_damage" noenhanced
set grid
set key outside right top noenhanced
plot "kappa_damage_vs_cohesive_stiffness.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse, μ = 0.5", \
     "kappa_damage_vs_cohesive_stiffness.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "inhouse, μ = 0.02"
