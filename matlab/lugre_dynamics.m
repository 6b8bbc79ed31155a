function r = lugre_dynamics(scenario, times, rtol)
%LUGRE_DYNAMICS  The closed-loop experiments of Canudas de Wit et al. (1995).
%   r = lugre_dynamics(scenario, times, rtol) runs 'presliding', 'breakaway' (10 N/s),
%   'stick-slip', 'lag' or 'pid' (Table I, a 1 kg mass, from rest; as
%   `lugre dynamics --scenario`) at relative tolerance rtol (default 1e-8) and returns the
%   position x [m], velocity v [m/s], bristle deflection z [m] and friction force [N] at the
%   given times (strictly increasing, inside the scenario's run).
  if nargin < 3, rtol = 0; end
  r = lugre_mex('dynamics', scenario, times, rtol);
end
