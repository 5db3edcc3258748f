set terminal png size 900,600 enhanced font 'DejaVu Sans,11'
set output "largest_departed_fragment_vs_max_1.png"
set title "largest_departed_fragment against outlet corner from y (m)" noenhanced
set xlabel "outlet corner from y (m)" noenhanced
set ylabel "largest_departed_fragment" noenhanced
set grid
set key outside right top noenhanced
plot "largest_departed_fragment_vs_max_1.dat" index 0 using 1:2:3 with yerrorlines lw 2 title "inhouse"
