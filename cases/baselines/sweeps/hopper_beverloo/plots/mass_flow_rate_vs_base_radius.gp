set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "mass_flow_rate_vs_base_radius.png"
set title "mass_flow_rate against orifice radius (m)" noenhanced
set xlabel "orifice radius (m)" noenhanced
set ylabel "mass_flow_rate" noenhanced
set grid
set key outside right top noenhanced
plot "mass_flow_rate_vs_base_radius.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse", \
     "mass_flow_rate_vs_base_radius.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "lammps"
