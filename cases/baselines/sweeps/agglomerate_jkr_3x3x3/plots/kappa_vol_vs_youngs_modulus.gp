set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "kappa_vol_vs_youngs_modulus.png"
set title "kappa_vol against E (Pa) (γ (J/m²) = 121.5)" noenhanced
set xlabel "E (Pa)" noenhanced
set ylabel "kappa_vol" noenhanced
set grid
set key outside right top noenhanced
set logscale x
set format x '10^{%T}'
plot "kappa_vol_vs_youngs_modulus.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse, μ = 0.02", \
     "kappa_vol_vs_youngs_modulus.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "inhouse, μ = 0.2", \
     "kappa_vol_vs_youngs_modulus.dat" index 2 using 1:2:3 with yerrorlines lw 2 title "inhouse, μ = 2"
