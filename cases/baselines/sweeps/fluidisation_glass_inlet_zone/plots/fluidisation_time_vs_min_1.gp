set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "fluidisation_time_vs_min_1.png"
set title "fluidisation_time against inlet corner to y (m)" noenhanced
set xlabel "inlet corner to y (m)" noenhanced
set ylabel "fluidisation_time" noenhanced
set grid
set key outside right top noenhanced
plot "fluidisation_time_vs_min_1.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse"
