function r = lugre_simulate(t, x, params, z0)
%LUGRE_SIMULATE  The response of a model to a sampled displacement.
%   r = lugre_simulate(t, x, params, z0): x(t) linear between the samples (strictly increasing
%   t, in s; x in m). The struct params names the model as lugre_loop takes it:
%     LuGre (default; or params.model = 'dahl'): bristle deflection z0 at t(1) (default 0).
%       Returns r.t, r.x, r.z (the deflection) and r.F (the friction force, N) at every
%       sample: the value just after the kink there (at the last sample, with the last
%       segment's velocity), as `lugre simulate --input` (gamma = 1). Exact at any stiffness.
%     a model of the zoo (params.model = 'elastoplastic', ...; lugre_models lists them): from
%       rest, as `lugre simulate --model NAME --input` (exact for a rate-independent model, at
%       finite rate where the model has rate dependence); z0 is refused. Returns r.t, r.x and
%       r.F (the force, N) at every sample.
%   Example: r = lugre_simulate([0 1 2 3], [0 1 -1 0.5], struct('model', 'elastoplastic'))
  if nargin < 3, params = struct(); end
  if nargin < 4, z0 = []; end
  r = lugre_mex('simulate', t, x, params, z0);
end
