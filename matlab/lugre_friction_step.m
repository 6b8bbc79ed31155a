function [F, z] = lugre_friction_step(x, dt, params, z0, x0)
%LUGRE_FRICTION_STEP  The friction element, step by step (for a host loop or a Simulink block).
%   [F, z] = lugre_friction_step(x, dt, params, z0, x0) moves the relative displacement from
%   x0 (default 0; bristle deflection z0, default 0) to x(1), x(2), ... each over dt seconds
%   (a scalar, or one per step), the displacement linear in time over a step (exact at any
%   stiffness), and returns the friction force F [N] and the deflection z [m] after each step.
%   Continue a run with lugre_friction_step(x_next, dt, params, z(end), x(end)).
  if nargin < 3, params = struct(); end
  if nargin < 4, z0 = 0; end
  if nargin < 5, x0 = 0; end
  [F, z] = lugre_mex('friction_step', x, dt, params, z0, x0);
end
