function r = lugre_sweep(amplitudes, frequencies, params, offset, tol)
%LUGRE_SWEEP  The periodic steady state of the LuGre model under sines, over a grid.
%   r = lugre_sweep(amplitudes, frequencies, params, offset, tol): for every amplitude A (m)
%   with every frequency f (Hz), the steady state under u = offset + A sin(2 pi f t) (offset
%   default 0; tol the integrator's relative tolerance, default 1e-12), as `lugre sweep`.
%   Returns one column per quantity, one row per point (the frequencies of the first amplitude
%   first): r.amplitude, r.frequency, r.dissipation (energy per cycle, J), r.work,
%   r.stored_energy_change, r.peak_force (N), r.stiffness (N/m), r.damping (N s/m), r.gain,
%   r.phase (rad), r.a1, r.b1 (the force's first Fourier coefficients).
  if nargin < 3, params = struct(); end
  if nargin < 4, offset = []; end
  if nargin < 5, tol = []; end
  r = lugre_mex('sweep', amplitudes, frequencies, params, offset, tol);
end
