set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "orf_curves_inhouse.png"
set title "ORF against time, mean over the seeds (inhouse)" noenhanced
set xlabel "time (s)" noenhanced
set ylabel "obscured reservoir fraction" noenhanced
set grid
set key outside right top noenhanced
plot "orf_curves_inhouse.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "outlet corner from y (m) = 0.002", \
     "orf_curves_inhouse.dat" index 1 using 1:2:3 with yerrorlines lw 2 title "outlet corner from y (m) = 0.003", \
     "orf_curves_inhouse.dat" index 2 using 1:2:3 with yerrorlines lw 2 title "outlet corner from y (m) = 0.001"
