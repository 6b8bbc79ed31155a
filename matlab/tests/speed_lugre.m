function speed_lugre()
%SPEED_LUGRE  The MEX functions on the 10^6-sample walk that `cargo run --release -p lugre-ffi
%   --example speed` writes (and times through the core and the C ABI): best of 7, the
%   conversions to and from MATLAB arrays included.
%     octave --no-gui --quiet --eval "addpath('matlab', 'matlab/tests'); speed_lugre"
  f = fopen(fullfile(tempdir, 'lugre-speed-walk.f64'), 'r');
  u = fread(f, Inf, 'double', 0, 'ieee-le');
  fclose(f);
  t = (0:numel(u) - 1)' * 1e-3;
  p = struct('preset', 'canudas1995');
  ts = best_of(@() lugre_simulate(t, u, p));
  tc = best_of(@() lugre_cycles(u));
  printf('MEX, %d samples, best of 7: simulate %.2f ms, cycles %.2f ms\n', numel(u), ts * 1e3, tc * 1e3);
end

function s = best_of(g)
  s = Inf;
  for k = 1:7
    tic;
    g();
    s = min(s, toc);
  end
end
