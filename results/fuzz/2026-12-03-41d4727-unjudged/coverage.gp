set terminal svg size 900,500 dynamic background rgb 'white'
set output '/work/main/results/fuzz/2026-12-03-41d4727-unjudged/coverage.svg'
set xlabel 'seconds into the target''s run'
set ylabel 'coverage (edges)'
set key bottom right
set logscale y
plot '/work/main/results/fuzz/2026-12-03-41d4727-unjudged/fuzz_clip_exact.coverage' using 1:2 with lines title 'fuzz_clip_exact'
