function [names, table] = lugre_parameters(model)
%LUGRE_PARAMETERS  The parameter names of a model, from the core's table.
%   names = lugre_parameters('lugre') is {'sigma0', 'sigma1', 'sigma2', 'fc', 'fs', 'vs',
%   'beta'} (a cell array, in the order of the fit's arrays and the C ABI's LugreParams);
%   lugre_parameters('dahl') is {'rho', 'fc'}. The names are those the parameter structs of
%   lugre_loop, lugre_cycles, lugre_simulate and lugre_fit take.
%   For a model of the zoo (lugre_models lists them), e.g. lugre_parameters('maxwell-slip'),
%   [names, table] = lugre_parameters(model) also gives a struct array, one row per parameter:
%   name, unit, description, domain, shape ('scalar' or 'elements': one value per element)
%   and default (a row vector).
  if nargin < 1, model = 'lugre'; end
  if nargout > 1
    [names, table] = lugre_mex('parameters', model);
  else
    names = lugre_mex('parameters', model);
  end
end
