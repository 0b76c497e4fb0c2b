set terminal pngcairo size 900,560
set output 'docs/scaling_armadillo.png'
set logscale x
set grid
set xlabel 'input faces'
set ylabel 'wall time per input face (microseconds)'
set key outside right
set yrange [0:*]
plot 'docs/scaling_armadillo.png.dat' index 0 using 1:7 with linespoints lw 2 title 'whole pipeline, 1 thread', 'docs/scaling_armadillo.png.dat' index 0 using 1:6 with linespoints title 'Q-Morph, 1 thread', 'docs/scaling_armadillo.png.dat' index 0 using 1:3 with linespoints dt 2 title 'VSA, 1 thread', 'docs/scaling_armadillo.png.dat' index 1 using 1:7 with linespoints lw 2 title 'whole pipeline, 2 threads', 'docs/scaling_armadillo.png.dat' index 1 using 1:6 with linespoints title 'Q-Morph, 2 threads', 'docs/scaling_armadillo.png.dat' index 1 using 1:3 with linespoints dt 2 title 'VSA, 2 threads'
