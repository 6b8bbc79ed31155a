function r = lugre_simulate(t, x, params, z0)
%LUGRE_SIMULATE  The exact response of the LuGre model to a sampled displacement.
%   r = lugre_simulate(t, x, params, z0): x(t) linear between the samples (strictly increasing
%   t, in s; x in m), bristle deflection z0 at t(1) (default 0). Returns r.t, r.x, r.z (the
%   deflection) and r.F (the friction force, N) at every sample: the value just after the
%   kink there (at the last sample, with the last segment's velocity), as
%   `lugre simulate --input` (gamma = 1). Exact at any stiffness.
  if nargin < 3, params = struct(); end
  if nargin < 4, z0 = 0; end
  r = lugre_mex('simulate', t, x, params, z0);
end
