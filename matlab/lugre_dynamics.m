function r = lugre_dynamics(request, times, rtol)
%LUGRE_DYNAMICS  A mass with LuGre friction driven by forces, a spring, a PID controller or a
%   prescribed velocity; the closed-loop experiments of Canudas de Wit et al. (1995).
%
%   r = lugre_dynamics(request) runs the core's dynamics request (as `lugre dynamics` and
%   Python's lugre.dynamics), one struct field per request field, by the same names:
%     scenario  'presliding', 'breakaway', 'stick-slip', 'lag' or 'pid': a preset (Table I, a
%               1 kg mass, its drive and its end) whose fields the others replace
%     model     a params struct as lugre_loop takes (struct('preset', 'canudas1995') or
%               struct('sigma0', 1e5, 'sigma1', 316, 'fc', 1, 'fs', 1.5, 'vs', 1e-3, 'beta', 2)),
%               or a model of the zoo with a finite-rate form: the elasto-plastic law
%               struct('model', 'elastoplastic', 'zba', 5e-6, ...) (its sigma0, sigma1,
%               sigma2, fc, fs, vs, beta, zba; the others the scenario's Table I, else the
%               table's defaults) or GMS struct('model', 'maxwell-slip', ...); needed unless a
%               scenario gives Table I
%     mass, damping, force_rate, spring, pull, t_end, rtol, atol, samples, loops   numbers
%     pid       [Kp Ki Kv];  setpoint  a number, or an N-by-2 matrix [t xd] of steps
%     force, input, end, velocity   N-by-2 matrices [t value] (linear between the points)
%     times     the output times (the run ends at the last unless t_end is given)
%   and returns r.t, r.x, r.v, r.z, r.friction, r.drive (columns), r.t_end, r.energy (input,
%   stored_start, stored_end, dissipated), r.stats (steps, rejected, events), r.breakaway (t,
%   force, x with a force ramp, else []), r.slip_onsets (how many), r.period and r.loops: the
%   friction-displacement loops (asked for with loops = 1, on by default for 'presliding';
%   else 0-by-1), a struct array with the fields of `lugre dynamics --json`'s loops: t_start,
%   t_turn, t_close, turning_points (a column), work, bristle_energy_change, dissipation,
%   rate_independent_work.
%   Example: r = lugre_dynamics(struct('scenario', 'pid', 'pid', [3 8 6], 't_end', 40));
%
%   r = lugre_dynamics(scenario) runs a scenario alone (its run, 1001 samples).
%   r = lugre_dynamics(scenario, times, rtol) is the shorthand of the scenario at those times
%   (rtol default 1e-8): r.t, r.x, r.v, r.z, r.friction.
  if nargin == 1 && ischar(request)
    % A scenario alone: its own run and 1001 samples.
    request = struct('scenario', request);
  end
  if nargin == 1
    r = lugre_mex('dynamics', request);
    return;
  end
  if nargin < 3, rtol = 0; end
  r = lugre_mex('dynamics', request, times, rtol);
end
