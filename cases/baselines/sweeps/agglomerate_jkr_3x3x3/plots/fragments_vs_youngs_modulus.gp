set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "fragments_vs_youngs_modulus.png"
set title "fragments against E (Pa) (γ (J/m²) = 121.5)" noenhanced
set xlabel "E (Pa)" noenhanced
set ylabel "fragments" noenhanced
set grid
set key outside right top noenhanced
set logscale x
set format x '10^{%T}'
plot "fragments_vs_youngs_modulus.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse, μ = 0.02", \
     "fragments_vs_youngs_modulus.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "inhouse, μ = 0.2", \
     "fragments_vs_youngs_modulus.dat" index 2 using 1:2:3 with yerrorlines lw 2 title "inhouse, μ = 2"
