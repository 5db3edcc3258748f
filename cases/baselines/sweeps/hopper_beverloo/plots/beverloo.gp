set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "beverloo.png"
set title "Mass flow rate against the orifice diameter, with Beverloo's law fitted" noenhanced
set xlabel "orifice diameter D (m)" noenhanced
set ylabel "mass flow rate W (kg/s)" noenhanced
set grid
set key outside right top noenhanced
plot "beverloo.dat" index 0 using 1:2:3 with yerrorbars lw 2 title "inhouse (mean ± s.e.)", \
     "beverloo.dat" index 1 using 1:2 with lines lw 2 title "inhouse: C = 0.507, k = 1.43", \
     "beverloo.dat" index 2 using 1:2:3 with yerrorbars lw 2 title "lammps (mean ± s.e.)", \
     "beverloo.dat" index 3 using 1:2 with lines lw 2 title "lammps: C = 0.505, k = 1.42"
