set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "orf_curves_lammps.png"
set title "ORF against time, mean over the seeds (lammps)" noenhanced
set xlabel "time (s)" noenhanced
set ylabel "obscured reservoir fraction" noenhanced
set grid
set key outside right top noenhanced
plot "orf_curves_lammps.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "orifice radius (m) = 0.005", \
     "orf_curves_lammps.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "orifice radius (m) = 0.006", \
     "orf_curves_lammps.dat" index 2 using 1:2:3 with yerrorlines lw 2 title "orifice radius (m) = 0.007", \
     "orf_curves_lammps.dat" index 3 using 1:2:3 with yerrorlines lw 2 title "orifice radius (m) = 0.008"
