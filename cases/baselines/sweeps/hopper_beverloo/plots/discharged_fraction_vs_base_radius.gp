set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "discharged_fraction_vs_base_radius.png"
set title "discharged_fraction against orifice radius (m)" noenhanced
set xlabel "orifice radius (m)" noenhanced
set ylabel "discharged_fraction" noenhanced
set grid
set key outside right top noenhanced
plot "discharged_fraction_vs_base_radius.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse", \
     "discharged_fraction_vs_base_radius.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "lammps"
