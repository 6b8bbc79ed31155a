function r = lugre_loop(u, params, n)
%LUGRE_LOOP  The hysteresis loop y° of the LuGre/Dahl model for a periodic input.
%   r = lugre_loop(u, params) takes one period's turning points u (as
%   `lugre loop --turning-points`) and a parameter struct (fields sigma0, sigma1, sigma2,
%   fc, fs, vs, beta in SI units, or preset = 'canudas1995'; missing fields take the CLI's
%   defaults) and returns a struct. Numbers of any real class (single, int32, ...) or
%   logical are taken as double, in arguments and fields; a matrix is refused:
%     r.u, r.rho, r.y      the turning points, the total variation there, y° there [N]
%     r.loops              the loop table (as `lugre loop --json`'s loops), column vectors:
%                          kind (0 major, 1 minor), start_/reversal_/end_ rho, u, y, work,
%                          stored_energy_change, dissipation, closure_gap, parent (the
%                          row of the enclosing loop, 1-based; 0: none), depth
%     r.work_per_period    the energy dissipated per period [J], r.period [m]
%     r.curve              with n (lugre_loop(u, params, n), 2 <= n <= 1e8): y° at n points
%                          evenly spaced over the period, both ends included: columns
%                          r.curve.rho, r.curve.u, r.curve.y ([] without n)
%   Example: r = lugre_loop([0 1 0.5 1.5], struct('sigma0', 6))
  if nargin < 2
    params = struct();
  end
  if nargin < 3
    n = [];
  end
  r = lugre_mex('loop', u, params, n);
end
