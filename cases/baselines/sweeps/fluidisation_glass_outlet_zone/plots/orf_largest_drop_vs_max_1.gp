set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "orf_largest_drop_vs_max_1.png"
set title "orf_largest_drop against outlet corner from y (m)" noenhanced
set xlabel "outlet corner from y (m)" noenhanced
set ylabel "orf_largest_drop" noenhanced
set grid
set key outside right top noenhanced
plot "orf_largest_drop_vs_max_1.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse"
