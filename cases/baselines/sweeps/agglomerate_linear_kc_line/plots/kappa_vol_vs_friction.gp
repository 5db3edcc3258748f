set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "kappa_vol_vs_friction.png"
set title "kappa_vol against μ" noenhanced
set xlabel "μ" noenhanced
set ylabel "kappa_vol" noenhanced
set grid
set key outside right top noenhanced
plot "kappa_vol_vs_friction.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_c (N/m) = 10", \
     "kappa_vol_vs_friction.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_c (N/m) = 25", \
     "kappa_vol_vs_friction.dat" index 2 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_c (N/m) = 50", \
     "kappa_vol_vs_friction.dat" index 3 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_c (N/m) = 100", \
     "kappa_vol_vs_friction.dat" index 4 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_c (N/m) = 150", \
     "kappa_vol_vs_friction.dat" index 5 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_c (N/m) = 200", \
     "kappa_vol_vs_friction.dat" index 6 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_c (N/m) = 250", \
     "kappa_vol_vs_friction.dat" index 7 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_c (N/m) = 300", \
     "kappa_vol_vs_friction.dat" index 8 using 1:2:3 with yerrorlines lw 2 title "inhouse, k_c (N/m) = 400"
