function failures = test_lugre()
%TEST_LUGRE  The MEX functions against the CLI's JSON (to the last digit) and bad input.
%   Run from the repository root after `bash scripts/build-mex.sh` and
%   `cargo build --release -p lugre-cli`:
%     octave --no-gui --quiet --eval "addpath('matlab', 'matlab/tests'); exit(test_lugre())"
%   Returns the number of failed checks (0: all passed). The CLI is $LUGRE_EXE or
%   target/release/lugre.
  failures = 0;
  exe = getenv('LUGRE_EXE');
  if isempty(exe)
    exe = 'target/release/lugre';
  end
  % Octave's jsondecode does not round every decimal correctly (it gave ...944 for
  % -1.9573070266459942): the numbers are read from the JSON text with str2double instead.
  cli = @(args) run_cli(exe, args);

  % The loop: y° at the turning points and the loop table, as `lugre loop --json`.
  r = lugre_loop([0 1 0.5 1.5], struct('sigma0', 6));
  j = cli('loop --sigma0 6 --turning-points 0,1,0.5,1.5 --json');
  tp = between(j, '"turning_points":', '"loops":');
  failures += expect(isequal(r.y, numbers(tp, 'y')), 'loop: y at the turning points');
  failures += expect(isequal(r.rho, numbers(tp, 'rho')), 'loop: rho');
  failures += expect(isequal(r.loops.work, numbers(j, 'work')), 'loop: work of each loop');
  failures += expect(isequal(r.loops.closure_gap, numbers(j, 'closure_gap')), 'loop: closure gaps');
  failures += expect(isequal(r.work_per_period, numbers(j, 'work_per_period')), 'loop: work per period');
  kinds = regexp(j, '"kind":"(major|minor)"', 'tokens');
  failures += expect(isequal(r.loops.kind, strcmp([kinds{:}], 'minor')'), 'loop: kinds');

  % Rainflow cycles with energies, as `lugre cycles --json`.
  h = [-2 1 -3 5 -1 3 -4 4 -2];
  c = lugre_cycles(h, 0, struct('sigma0', 6));
  j = between(cli('cycles --values -2,1,-3,5,-1,3,-4,4,-2 --energy --sigma0 6 --fs 2 --json'), ...
              '"cycles":', '"samples":');
  failures += expect(isequal(c.range, numbers(j, 'range')), 'cycles: ranges');
  failures += expect(isequal(c.count, numbers(j, 'count')), 'cycles: counts');
  failures += expect(isequal(c.start, numbers(j, 'start')), 'cycles: start indices');
  full = c.count == 1;
  failures += expect(isequal(c.work(full), numbers(j, 'work')), 'cycles: work of the full cycle');
  failures += expect(isequal(c.closure_position(full), numbers(j, 'closure_position')), 'cycles: closure');

  % The closed-loop stick-slip experiment, as `lugre dynamics --json`.
  d = lugre_dynamics('stick-slip', [10 20 30]);
  j = cli('dynamics --scenario stick-slip --times 10,20,30 --json');
  failures += expect(isequal(d.x, array(j, 'x')), 'dynamics: x');
  failures += expect(isequal(d.friction, array(j, 'friction')), 'dynamics: friction');

  % The friction element stepped through the knots is the exact simulation there.
  p = struct('preset', 'canudas1995');
  t = [0 5e-3 1e-2 1.5e-2 2e-2];
  x = [0 5e-6 1e-5 1e-5 -2e-6];
  s = lugre_simulate(t, x, p);
  [F, z] = lugre_friction_step(x(2:end), diff(t), p);
  failures += expect(isequal(z, s.z(2:end)), 'friction_step: z is the simulation''s');
  failures += expect(isequal(F(end), s.F(end)), 'friction_step: the last force');
  [F2, z2] = lugre_friction_step(x(4:end), diff(t(3:end)), p, z(2), x(3));
  failures += expect(isequal(z2, z(3:end)), 'friction_step: a run continued');

  % Bad input: a MATLAB error with lugre's message, and Octave goes on.
  failures += raises(@() lugre_loop([0 NaN 1]), 'u[1] = NaN is not a finite number');
  failures += raises(@() lugre_loop('abc'), 'u must be a real double array');
  failures += raises(@() lugre_loop([0 1], struct('sigma0', -1)), 'sigma0 must be > 0, got -1');
  failures += raises(@() lugre_loop([0 1], struct('sigma9', 1)), 'unknown parameter ''sigma9''');
  failures += raises(@() lugre_loop([0 1], struct('sigma0', [1 2])), 'sigma0 must be a scalar');
  failures += raises(@() lugre_simulate([0 1 2], [0 1]), 't and x must have the same length');
  failures += raises(@() lugre_simulate([0 1 1], [0 1 2]), 'strictly increasing');
  failures += raises(@() lugre_friction_step([1e-6 2e-6], 0, p), 'cannot move in a zero step');
  failures += raises(@() lugre_dynamics('nope', [1 2]), 'unknown scenario ''nope''');
  failures += raises(@() lugre_cycles([0 Inf 1]), 'u[1] = inf is not a finite number');
  if failures == 0
    printf('test_lugre: all checks passed\n');
  else
    printf('test_lugre: %d checks FAILED\n', failures);
  end
end

function text = run_cli(exe, args)
  [status, text] = system([exe ' ' args]);
  if status ~= 0
    error('the CLI failed: %s %s: %s', exe, args, text);
  end
end

function v = numbers(text, key)
% Every number after "key": in the JSON text (null skipped), in order, as a column.
  tokens = regexp(text, ['"' key '":(-?[0-9][0-9.eE+-]*)'], 'tokens');
  v = str2double([tokens{:}])';
end

function v = array(text, key)
% The numbers of the array "key":[...].
  body = regexp(text, ['"' key '":\[([^\]]*)\]'], 'tokens', 'once');
  v = str2double(strsplit(body{1}, ','))';
end

function s = between(text, from, to)
  a = strfind(text, from);
  b = strfind(text, to);
  s = text(a(1):b(1));
end

function failed = expect(ok, what)
  failed = ~ok;
  if failed
    printf('FAILED: %s\n', what);
  end
end

function failed = raises(f, message)
  failed = true;
  try
    f();
    printf('FAILED: no error (wanted "%s")\n', message);
  catch err
    if ~isempty(strfind(err.message, message)) && strcmp(err.identifier, 'lugre:error')
      failed = false;
    else
      printf('FAILED: error "%s" (%s), wanted "%s"\n', err.message, err.identifier, message);
    end
  end
end
