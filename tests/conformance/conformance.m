function failures = conformance()
%CONFORMANCE  The conformance table (tests/conformance/cases.json, format in its README)
%   through the MEX functions: every case that names `mex` calls lugre_loop, lugre_cycles,
%   lugre_simulate, lugre_friction_step, lugre_fit or lugre_dynamics with its fields; an
%   accepted case's numbers must be the CLI's --json to the last bit (`same`) and pass its
%   `checks`, a refused one must raise an error with identifier lugre:error and the message of
%   `error` (fields spelled by their core names, indices 1-based: u(2)).
%   Run from the repository root after `bash scripts/build-mex.sh` and
%   `cargo build --release -p lugre-cli`:
%     octave --no-gui --quiet --eval "addpath('matlab', 'tests/conformance'); exit(conformance())"
%   Returns the number of failed cases (0: all passed). The CLI is $LUGRE_EXE, else
%   target/release/lugre (under $CARGO_TARGET_DIR if set). Octave's jsondecode rounds some
%   decimals wrongly (...944 for -1.9573070266459942), so the JSON is read here, each number
%   by str2double.
  failures = 0;
  exe = getenv('LUGRE_EXE');
  if isempty(exe)
    target = getenv('CARGO_TARGET_DIR');
    if isempty(target)
      target = 'target';
    end
    exe = fullfile(target, 'release', 'lugre');
  end
  here = fileparts(mfilename('fullpath'));
  table = json_read(fileread(fullfile(here, 'cases.json')));
  ran = 0;
  for k = 1:numel(table.cases)
    c = table.cases{k};
    if ~any(strcmp(c.front_ends, 'mex'))
      continue;
    end
    ran += 1;
    problem = run_case(c, table, exe);
    if ~isempty(problem)
      failures += 1;
      printf('FAILED %s [mex]: %s\n', c.id, problem);
    end
  end
  printf('conformance: %d cases through the MEX functions, %d failed\n', ran, failures);
end

% ---- one case

function problem = run_case(c, table, exe)
  problem = '';
  try
    got = mex_answer(c);
  catch err
    % Octave puts the MEX function's name before its message (MATLAB does not).
    err = struct('identifier', err.identifier, 'message', regexprep(err.message, '^lugre_mex: ', ''));
    if ~isfield(c, 'error')
      problem = ['refused: ' err.message];
    elseif ~strcmp(err.identifier, 'lugre:error')
      problem = sprintf('error identifier %s: %s', err.identifier, err.message);
    elseif ~strcmp(err.message, expected_message(c, table))
      problem = sprintf('message\n    got  %s\n    want %s', err.message, expected_message(c, table));
    end
    return;
  end
  if isfield(c, 'error')
    problem = ['accepted, wanted "' c.error.message '"'];
    return;
  end
  checks = field_or(c.ok, 'checks', {});
  for j = 1:numel(checks)
    problem = check(got, checks{j}{:});
    if ~isempty(problem)
      return;
    end
  end
  if any(strcmp(c.front_ends, 'cli'))
    reference = cli_answer(c, exe);
    same = expand(field_or(c.ok, 'same', {}), table.sets);
    for j = 1:numel(same)
      if iscell(same{j})
        [theirs, ours] = deal(same{j}{1}, same{j}{2});
      else
        [theirs, ours] = deal(same{j}, same{j});
      end
      a = select(reference, theirs);
      b = select(got, ours);
      if isempty(a) || numel(a) ~= numel(b) || ~all(cellfun(@bits_equal, a, b))
        problem = sprintf('%s is not the CLI''s %s:\n    got  %s\n    CLI  %s', ours, theirs, show(b), show(a));
        return;
      end
    end
  end
end

function out = expand(same, sets)
% `@name` entries of `same`: the table's set of paths of that name.
  out = {};
  for j = 1:numel(same)
    s = same{j};
    if ischar(s) && s(1) == '@'
      out = [out, sets.(s(2:end))];
    else
      out{end + 1} = s;
    end
  end
end

function m = expected_message(c, table)
% The message with {name} spelled as the MEX functions spell it (the core's names, unless the
% case or the table says otherwise) and {at:k}, {item:k} as MATLAB counts, (k+1).
  m = '';
  rest = c.error.message;
  while any(rest == '{')
    open = find(rest == '{', 1);
    close = find(rest == '}', 1);
    name = rest(open + 1:close - 1);
    colon = find(name == ':', 1);
    if strcmp(name, '@lugre_parameters')   % the core's table: a parameter added needs no edit
      word = strjoin(lugre_parameters('lugre'), ', ');
    elseif ~isempty(colon)   % {at:k}, {item:k}: element k (0-based) of an array, as MATLAB counts
      word = sprintf('(%d)', str2double(name(colon + 1:end)) + 1);
    else
      word = name;
      spell = field_or(c, 'spell', struct());
      if isfield(spell, name) && isfield(spell.(name), 'mex')
        word = spell.(name).mex;
      elseif isfield(table.spelling, 'mex') && isfield(table.spelling.mex, name)
        word = table.spelling.mex.(name);
      end
    end
    m = [m rest(1:open - 1) word];
    rest = rest(close + 1:end);
  end
  m = [m rest];
end

function problem = check(v, path, op, want)
  problem = '';
  got = select(v, path);
  if isempty(got)
    problem = [path ' selects nothing'];
    return;
  end
  for j = 1:numel(got)
    g = got{j};
    switch op
      case '==', ok = isequal(g, want);
      case '!=', ok = ~isequal(g, want);
      case '<', ok = g < want;
      case '<=', ok = g <= want;
      case '>', ok = g > want;
      case '>=', ok = g >= want;
    end
    if ~ok
      problem = sprintf('check %s %s %s fails: %s', path, op, show({want}), show({g}));
      return;
    end
  end
end

function ok = bits_equal(a, b)
  if isnumeric(a) && isnumeric(b) && isscalar(a) && isscalar(b)
    ok = typecast(double(a), 'uint64') == typecast(double(b), 'uint64');
  else
    ok = isequal(a, b) && strcmp(class(a), class(b));
  end
end

function s = show(values)
  s = strjoin(cellfun(@(x) num2str(x, 17), values, 'UniformOutput', false), ' ');
end

% ---- paths: a.b keys, [] every element, [k] one (negative from the end), [k:] from k; #: count

function out = select(v, path)
  if path(1) == '#'
    inner = select(v, path(2:end));
    out = {numel(inner)};
    return;
  end
  current = {v};
  for segment = strsplit(path, '.')
    s = segment{1};
    open = find(s == '[', 1);
    if isempty(open)
      [key, rest] = deal(s, '');
    else
      [key, rest] = deal(s(1:open - 1), s(open:end));
    end
    next = {};
    for j = 1:numel(current)
      x = current{j};
      if isstruct(x) && isfield(x, key)
        next{end + 1} = x.(key);
      else
        next{end + 1} = [];
      end
    end
    current = next;
    while ~isempty(rest)
      close = find(rest == ']', 1);
      inside = rest(2:close - 1);
      rest = rest(close + 1:end);
      next = {};
      for j = 1:numel(current)
        items = as_items(current{j});
        n = numel(items);
        if isempty(inside)
          next = [next, items];
        elseif inside(end) == ':'
          next = [next, items(str2double(inside(1:end - 1)) + 1:end)];
        else
          k = str2double(inside);
          k = k + (k < 0) * n + 1;
          if k >= 1 && k <= n
            next{end + 1} = items{k};
          else
            next{end + 1} = [];
          end
        end
      end
      current = next;
    end
  end
  % A path ending at an array selects its elements.
  if numel(current) == 1 && (iscell(current{1}) || (isnumeric(current{1}) && numel(current{1}) > 1))
    current = as_items(current{1});
  end
  out = current;
end

function items = as_items(x)
  if iscell(x)
    items = reshape(x, 1, []);
  elseif isnumeric(x) || islogical(x)
    items = num2cell(reshape(x, 1, []));
  else
    items = {x};
  end
end

% ---- the CLI's answer

function v = cli_answer(c, exe)
  dir = tempname();
  mkdir(dir);
  cleanup = onCleanup(@() remove_dir(dir));
  path = '';
  if isfield(c, 'file')
    path = fullfile(dir, c.file.name);
    cols = cellfun(@(name) reshape(numbers(c.fields.(name)), [], 1), c.file.columns, 'UniformOutput', false);
    fid = fopen(path, 'w');
    fprintf(fid, '%s\n', c.file.header);
    fprintf(fid, [strjoin(repmat({'%.17g'}, 1, numel(cols)), ',') '\n'], [cols{:}]');
    fclose(fid);
  end
  args = c.cli;
  for j = 1:numel(args)
    args{j} = strrep(strrep(args{j}, '@dir/', [dir '/']), '@file', path);
  end
  [status, text] = system([exe ' ' strjoin(cellfun(@(a) ['''' a ''''], args, 'UniformOutput', false), ' ')]);
  if status ~= 0
    error('conformance:cli', 'the CLI refused %s: %s', strjoin(args, ' '), text);
  end
  v = json_read(text);
end

function remove_dir(dir)
  confirm_recursive_rmdir(false);
  rmdir(dir, 's');
end

% ---- the MEX functions, their answers in the shape of the CLI's JSON (0-based indices)

function got = mex_answer(c)
  f = c.fields;
  classes = struct();
  if isfield(c, 'mex') && isfield(c.mex, 'classes')
    classes = c.mex.classes;
  end
  cast_as = @(name, value) cast_field(classes, name, value);
  switch c.command
    case 'loop'
      params = params_of(field_or(f, 'model', struct()), classes);
      u = cast_as('turning_points', numbers(f.turning_points));
      if isfield(f, 'samples')
        r = lugre_loop(u, params, f.samples);
      else
        r = lugre_loop(u, params);
      end
      got = loop_answer(r);
    case 'cycles'
      params = [];
      if isfield(f, 'model')
        params = params_of(f.model, classes);
      end
      r = lugre_cycles(cast_as('history', numbers(f.history)), field_or(f, 'gate', 0), params, field_or(f, 'x0', []));
      got = cycles_answer(r, isfield(f, 'model'));
    case 'simulate'
      r = lugre_simulate(numbers(f.t), numbers(f.x), params_of(field_or(f, 'model', struct()), classes), field_or(f, 'x0', []));
      if isfield(r, 'z')
        got = struct('t', r.t, 'u', r.x, 'z', r.z, 'y', r.F);
      else  % a model of the zoo: no state
        got = struct('t', r.t, 'u', r.x, 'y', r.F);
      end
    case 'element'
      x = numbers(f.x);
      if isfield(f, 'dt')
        dt = numbers(f.dt);
      else
        dt = diff(numbers(f.t));
      end
      [F, z] = lugre_friction_step(x(2:end), dt, params_of(field_or(f, 'model', struct()), classes), field_or(f, 'z0', 0), x(1));
      got = struct('z', z, 'F', F);
    case 'fit'
      got = fit_answer(f);
    case 'dynamics'
      got = dynamics_answer(f);
    case 'sweep'
      r = lugre_sweep(numbers(f.amplitudes), numbers(f.frequencies), params_of(field_or(f, 'model', struct()), classes), ...
                      field_or(f, 'offset', 0), field_or(f, 'tol', []));
      names = fieldnames(r);
      points = cell(1, numel(r.amplitude));
      for i = 1:numel(points)
        p = struct();
        for k = 1:numel(names)
          p.(names{k}) = r.(names{k})(i);
        end
        points{i} = p;
      end
      got = struct();
      got.points = points;
    otherwise
      error('conformance:case', 'the MEX functions have no command %s', c.command);
  end
end

function value = cast_field(classes, name, value)
% The value in the MATLAB class the case gives for a field or parameter of that name.
  if isfield(classes, name)
    value = cast(value, classes.(name));
  end
end

function p = params_of(m, classes)
% A parameter struct of the MEX functions (preset and values by the core's names; a model of
% the zoo by its name in `model`, its parameters by the table's names).
  p = struct();
  for name = fieldnames(m)'
    value = m.(name{1});
    if ~any(strcmp(name{1}, {'preset', 'model'}))
      value = cast_field(classes, name{1}, numbers(value));
    end
    p.(name{1}) = value;
  end
end

function got = loop_answer(r)
  tp = cell(1, numel(r.u));
  for i = 1:numel(r.u)
    tp{i} = point(r.rho(i), r.u(i), r.y(i));
  end
  t = r.loops;
  loops = cell(1, numel(t.kind));
  kinds = {'major', 'minor'};
  for i = 1:numel(t.kind)
    parent = [];
    if t.parent(i) > 0
      parent = t.parent(i) - 1;
    end
    loops{i} = struct('kind', kinds{t.kind(i) + 1}, ...
                      'start', point(t.start_rho(i), t.start_u(i), t.start_y(i)), ...
                      'reversal', point(t.reversal_rho(i), t.reversal_u(i), t.reversal_y(i)), ...
                      'end', point(t.end_rho(i), t.end_u(i), t.end_y(i)), ...
                      'work', t.work(i), 'stored_energy_change', t.stored_energy_change(i), ...
                      'dissipation', t.dissipation(i), 'closure_gap', t.closure_gap(i), ...
                      'parent', parent, 'depth', t.depth(i));
  end
  got = struct('period', r.period, 'work_per_period', r.work_per_period);
  got.turning_points = tp;
  got.loops = loops;
  if ~isempty(r.curve)
    pts = cell(1, numel(r.curve.rho));
    for i = 1:numel(pts)
      pts{i} = point(r.curve.rho(i), r.curve.u(i), r.curve.y(i));
    end
    got.points = pts;
  end
end

function p = point(rho, u, y)
  p = struct('rho', rho, 'u', u, 'y', y);
end

function got = cycles_answer(r, with_model)
  rows = cell(1, numel(r.range));
  for i = 1:numel(r.range)
    full = r.count(i) == 1;
    row = struct('range', r.range(i), 'mean', r.mean(i), 'count', r.count(i), ...
                 'start', r.start(i) - 1, 'end', r.end(i) - 1, 'closure', [], 'closure_position', [], ...
                 'work', [], 'stored_energy_change', [], 'dissipation', [], 'closure_gap', []);
    if full
      row.closure = r.closure(i) - 1;
      row.closure_position = r.closure_position(i) - 1;
    end
    if full && with_model
      row.work = r.work(i);
      row.stored_energy_change = r.stored_energy_change(i);
      row.dissipation = r.dissipation(i);
      row.closure_gap = r.closure_gap(i);
    end
    rows{i} = row;
  end
  got = struct();
  got.cycles = rows;
end

function got = fit_answer(f)
  options = struct();
  if isfield(f, 'kind')
    options.kind = f.kind;
  end
  if isfield(f, 't')
    options.t = numbers(f.t);
  end
  if isfield(f, 'family')
    options.model = f.family;
  end
  if isfield(f, 'fix')
    options.params = f.fix;
    options.fix = fieldnames(f.fix)';
  end
  for name = {'starts', 'x0'}
    if isfield(f, name{1})
      options.(name{1}) = f.(name{1});
    end
  end
  r = lugre_fit(numbers(f.u), numbers(f.f), options);
  parameters = struct();
  for i = 1:numel(r.names)
    parameters.(r.names{i}) = struct('value', r.value(i), 'stderr', r.stderr(i), ...
                                     'ci95', r.ci95(i, :), 'at_bound', logical(r.at_bound(i)));
  end
  got = struct('parameters', parameters, 'rms', r.rms, 'samples', r.samples, 'dof', r.dof, ...
               't_quantile', r.t_quantile, 'condition_number', r.condition_number, ...
               'iterations', r.iterations, 'evaluations', r.evaluations, 'starts', r.starts, ...
               'converged', logical(r.converged), 'turning_points', r.turning_points);
end

function got = dynamics_answer(f)
% The request struct, field by field in the table's order; points as N-by-2 [t value].
  request = struct();
  for name = fieldnames(f)'
    value = f.(name{1});
    if strcmp(name{1}, 'model')
      value = params_of(value, struct());
    elseif iscell(value) && all(cellfun(@isnumeric, value))
      value = cell2mat(value(:));
    elseif ~ischar(value) || any(strcmp(value, {'nan', 'inf', '-inf'}))
      value = numbers(value);
    end
    request.(name{1}) = value;
  end
  r = lugre_dynamics(request);
  got = struct('t', r.t, 'x', r.x, 'v', r.v, 'z', r.z, 'friction', r.friction, 'drive', r.drive);
  got.energy = r.energy;
  got.stats = struct('steps', r.stats.steps, 'rejected', r.stats.rejected);
  got.events = cell(1, r.stats.events);
  got.breakaway = r.breakaway;
  got.loops = num2cell(r.loops);   % the struct array as a list of loops
end

% ---- values and the table

function v = field_or(s, name, default)
  if isfield(s, name)
    v = s.(name);
  else
    v = default;
  end
end

function x = numbers(v)
% The numbers of a field ("nan", "inf", "-inf" for those JSON cannot hold).
  if iscell(v) && ~isempty(v) && all(cellfun(@(x) isnumeric(x) && numel(x) > 1, v))
    x = cell2mat(v(:));   % rows: a matrix
  elseif iscell(v)
    x = cellfun(@numbers, v);
  elseif ischar(v)
    x = str2double(strrep(v, 'inf', 'Inf'));
  else
    x = v;
  end
end

function v = json_read(text)
% A JSON document: objects as structs (fields in order), arrays of numbers as row vectors, of
% equal-length number arrays as matrices (one row each), other arrays as cells; null as [].
  tokens = regexp(text, '"(?:[^"\\]|\\.)*"|-?\d+(?:\.\d+)?(?:[eE][+-]?\d+)?|true|false|null|[\[\]{}:,]', 'match');
  [v, k] = json_value(tokens, 1);
  if k <= numel(tokens)
    error('conformance:json', 'trailing text in the JSON document');
  end
end

function [v, k] = json_value(tokens, k)
  t = tokens{k};
  switch t(1)
    case '{'
      v = struct();
      k += 1;
      while ~strcmp(tokens{k}, '}')
        key = json_string(tokens{k});
        [v.(key), k] = json_value(tokens, k + 2);
        if strcmp(tokens{k}, ',')
          k += 1;
        end
      end
      k += 1;
    case '['
      items = {};
      k += 1;
      while ~strcmp(tokens{k}, ']')
        [items{end + 1}, k] = json_value(tokens, k);
        if strcmp(tokens{k}, ',')
          k += 1;
        end
      end
      k += 1;
      v = json_array(items);
    case '"'
      v = json_string(t);
      k += 1;
    otherwise
      switch t
        case 'true', v = true;
        case 'false', v = false;
        case 'null', v = [];
        otherwise, v = str2double(t);
      end
      k += 1;
  end
end

function v = json_array(items)
  scalar_number = @(x) isnumeric(x) && isscalar(x);
  if ~isempty(items) && all(cellfun(scalar_number, items))
    v = cell2mat(items);
  elseif ~isempty(items) && all(cellfun(@(x) isnumeric(x) && isrow(x) && numel(x) == numel(items{1}) && numel(x) > 1, items))
    v = items;   % points: kept as rows, made a matrix where a field takes one
  else
    v = items;
  end
end

function s = json_string(t)
  s = t(2:end - 1);
  s = regexprep(s, '\\"', '"');
  s = regexprep(s, '\\\\', '\\');
end
