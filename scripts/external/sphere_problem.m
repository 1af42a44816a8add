% The sphere f(x) = sum(x.^2) on [-5, 5]^dim as an mhbench external problem, in Octave (7 or
% later: jsonencode/jsondecode). Run by mhbench as
%   external:cmd='octave --no-gui --quiet --no-window-system scripts/external/sphere_problem.m'
% (protocol: README, "External programs (any language)"). jsonencode writes doubles with their
% shortest round-trip text, so values reach mhbench exactly; inf and NaN would be written as
% null, which the protocol refuses: a model that can return them must send the strings "inf".
1;  % a script, not a function file: the function below is defined, then called

% One line of stdin without its newline, or -1 once mhbench has closed it. Read a character at a
% time: Octave's fgetl on a pipe waits for more input than one line (it fills a buffer first),
% which would deadlock against mhbench waiting for the answer.
function line = read_line ()
  line = "";
  while true
    c = fread (stdin, 1, "char=>char");
    if (isempty (c))
      if (isempty (line))
        line = -1;
      end
      return;
    elseif (c == "\n")
      return;
    end
    line(end + 1) = c;
  end
end

function serve ()
  while true
    line = read_line ();
    if (! ischar (line))
      return;  % mhbench closed our stdin
    end
    message = jsondecode (line);
    if (strcmp (message.type, "describe"))
      dim = 10;
      if (isfield (message.parameters, "dim"))
        dim = str2double (message.parameters.dim);
      end
      reply = struct ("type", "description", "version", "sphere-octave-1", "dimension", dim,
                      "lower", {-5 * ones(1, dim)}, "upper", {5 * ones(1, dim)});
    elseif (strcmp (message.type, "eval"))
      x = message.x;  % one row per point (jsondecode makes a matrix of equal-length arrays)
      reply = struct ("type", "values", "f", {num2cell(sum (x .^ 2, 2))'});
    end
    fputs (stdout, [jsonencode(reply) "\n"]);
    fflush (stdout);
  end
end

serve ();
