-- The robot's path following the debugger, in headless Neovim (called by
-- e2e.lua). nvim-dap is not installed here: a stand-in with nvim-dap's
-- registries (adapters, configurations, listeners) takes what
-- require('rapid.dap').setup() registers, and this file drives the real
-- `rapid dap` as nvim-dap would (the registered adapter and configuration,
-- the on_config listeners, each event to the `after` listeners). At a
-- breakpoint the page opens (vim.ui.open) and holds the stop; after a step
-- the script the open page reads holds the next stop, and the page is not
-- opened again.
return function(ctx)
  local check, expect = ctx.check, ctx.expect
  local TIMEOUT = ctx.timeout

  local SQUARE = {
    'MODULE Square',
    '  CONST robtarget pCorner := [[500, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];',
    '  PROC main()',
    '    MoveL pCorner, v200, fine, tool0;',
    '    MoveL Offs(pCorner, 100, 0, 0), v200, fine, tool0;',
    '    MoveL Offs(pCorner, 100, 100, 0), v200, fine, tool0;',
    '    TPWrite "done";',
    '  ENDPROC',
    'ENDMODULE',
  }

  --- nvim-dap's registries, as plugins use them.
  local function stand_in()
    local vivify = function()
      return setmetatable({}, {
        __index = function(t, k)
          rawset(t, k, {})
          return rawget(t, k)
        end,
      })
    end
    return {
      adapters = {},
      configurations = {},
      listeners = { before = vivify(), after = vivify(), on_config = {} },
    }
  end

  --- A session of `rapid dap` driven as nvim-dap drives it.
  local function start(dap, config)
    local session = { id = 1, events = {}, seq = 0 }
    local adapter = dap.adapters.rapid
    local buffer = ''
    local argv = { adapter.command }
    vim.list_extend(argv, adapter.args or {})
    session.proc = vim.system(argv, {
      stdin = true,
      stdout = function(_, data)
        buffer = buffer .. (data or '')
        while true do
          local header_end = buffer:find('\r\n\r\n', 1, true)
          if not header_end then
            return
          end
          local length = tonumber(buffer:sub(1, header_end):match('Content%-Length: *(%d+)'))
          if not length or #buffer < header_end + 3 + length then
            return
          end
          local body = buffer:sub(header_end + 4, header_end + 3 + length)
          buffer = buffer:sub(header_end + 4 + length)
          local message = vim.json.decode(body)
          vim.schedule(function()
            if message.type == 'event' then
              table.insert(session.events, message)
              for _, listener in pairs(dap.listeners.after['event_' .. message.event]) do
                listener(session, message.body)
              end
            end
          end)
        end
      end,
    })
    function session.send(command, arguments)
      session.seq = session.seq + 1
      local body = vim.json.encode({ seq = session.seq, type = 'request', command = command, arguments = arguments })
      session.proc:write(('Content-Length: %d\r\n\r\n%s'):format(#body, body))
    end
    function session.wait(event, count)
      local ok = vim.wait(TIMEOUT, function()
        local n = 0
        for _, e in ipairs(session.events) do
          n = n + (e.event == event and 1 or 0)
        end
        return n >= (count or 1)
      end, 20)
      expect(ok, 'no %s event within %d ms', event, TIMEOUT)
    end
    for _, listener in pairs(dap.listeners.on_config) do
      config = listener(config)
    end
    session.config = config
    return session
  end

  check('the path opens at a breakpoint and follows the debugger (rapid.dap with nvim-dap)', function()
    local dir = vim.fn.tempname()
    vim.fn.mkdir(dir, 'p')
    local file = dir .. '/Square.mod'
    vim.fn.writefile(SQUARE, file)
    local saved_dap, saved_open = package.loaded.dap, vim.ui.open
    local dap = stand_in()
    package.loaded.dap = dap
    local opened = {}
    vim.ui.open = function(path)
      table.insert(opened, path)
      return nil, nil
    end
    local session
    local ok, err = pcall(function()
      expect(require('rapid.dap').setup({ robot = 'IRB 1200-7/0.7' }), 'setup found no nvim-dap')
      expect(dap.adapters.rapid and dap.adapters.rapid.args[1] == 'dap', 'adapter %s', vim.inspect(dap.adapters.rapid))
      local config = vim.deepcopy(dap.configurations.rapid[1])
      expect(config.robot == 'IRB 1200-7/0.7', 'configuration %s', vim.inspect(config))
      config.program = file
      session = start(dap, config)
      local page = session.config.plot
      expect(type(page) == 'string' and page:match('%.html$'), 'no page asked for: %s', vim.inspect(session.config))
      local live = page:gsub('%.html$', '.live.js')
      session.send('initialize', { adapterID = 'rapid' })
      session.send('launch', session.config)
      session.send('setBreakpoints', { source = { path = file }, breakpoints = { { line = 6 } } })
      session.send('configurationDone', {})
      session.wait('stopped')
      session.wait('rapidPath')
      expect(#opened == 1 and opened[1] == page, 'vim.ui.open: %s (the page %s)', vim.inspect(opened), page)
      local text = table.concat(vim.fn.readfile(page), '\n')
      expect(text:find('"current":1', 1, true) and text:find('"name":"IRB 1200-7/0.7"', 1, true),
        'the page at the breakpoint holds no stop or arm')
      local state = table.concat(vim.fn.readfile(live), '\n')
      expect(state:find('"line":6', 1, true), 'the script at the breakpoint: %s', state:sub(1, 200))
      session.send('next', { threadId = 1 })
      session.wait('stopped', 2)
      session.wait('rapidPath', 2)
      state = table.concat(vim.fn.readfile(live), '\n')
      expect(state:find('^rapidFollow%(') and state:find('"line":7', 1, true) and state:find('"current":2', 1, true),
        'the script after the step: %s', state:sub(1, 200))
      expect(#opened == 1, 'the page was opened again: %s', vim.inspect(opened))
      session.send('continue', { threadId = 1 })
      session.wait('terminated')
      session.send('disconnect', {})
    end)
    if session then
      pcall(function()
        session.proc:kill(15)
      end)
    end
    package.loaded.dap, vim.ui.open = saved_dap, saved_open
    expect(ok, '%s', tostring(err))
  end)
end
