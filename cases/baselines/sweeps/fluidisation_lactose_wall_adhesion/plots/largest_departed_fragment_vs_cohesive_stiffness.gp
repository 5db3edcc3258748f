set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "largest_departed_fragment_vs_cohesive_stiffness.png"
set title "largest_departed_fragment against wall k_c (N/m)" noenhanced
set xlabel "wall k_c (N/m)" noenhanced
set ylabel "largest_departed_fragment" noenhanced
set grid
set key outside right top noenhanced
plot "largest_departed_fragment_vs_cohesive_stiffness.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse"
